//! `height_field`'s image → heights in [0, 1] (POV-Ray 3.4.5.1.6): a grey image's value over
//! its maximum; a palette image's index over 255; a colour image (PPM, TGA, colour PNG) holds a
//! 16-bit height in its red (high byte) and green (low byte) channels. The file is searched as
//! `#include` searches (the scene's folder, then the include path). PNG through the `png`
//! crate strahl already uses; GIF (palette index over 255) and POT (Fractint's 16-bit GIF,
//! high bytes left, low bytes right) through `crate::image_file`; PGM, PPM and TGA are a few
//! lines each.

use std::sync::Arc;

use super::Lowerer;
use crate::desc::{HeightFieldDesc, ShapeDesc};
use crate::image_file::{pnm_number, tga_pixels};
use crate::pov::source::{Diag, PResult, Span};

/// Largest image side read (POV-Ray reads larger; 2 × 8191² triangles is 134 M already).
const MAX_SIDE: usize = 8192;

impl Lowerer<'_> {
    /// Reads the `format` image `name` into a height field.
    pub(crate) fn height_field(
        &mut self,
        format: &str,
        name: &str,
        span: Span,
        smooth: bool,
        water_level: f64,
    ) -> PResult<ShapeDesc> {
        let path = if std::path::Path::new(name).is_file() {
            std::path::PathBuf::from(name)
        } else {
            self.files.data_path(name, false).map_err(|_| {
                Diag::new(
                    span,
                    format!(
                        "height_field image \"{name}\" not found (searched as written, the scene's folder and the \
                         include path)"
                    ),
                )
            })?
        };
        let bytes = std::fs::read(&path)
            .map_err(|e| Diag::new(span, format!("cannot read height_field image \"{}\": {e}", path.display())))?;
        let decoded = match format {
            "png" => png_heights(&bytes),
            "pgm" | "ppm" => pnm_heights(&bytes),
            "gif" => gif_heights(&bytes),
            "pot" => pot_heights(&bytes),
            "jpeg" => jpeg_heights(&bytes),
            _ => tga_heights(&bytes),
        };
        let (width, height, heights) =
            decoded.map_err(|m| Diag::new(span, format!("height_field: \"{}\" as {format}: {m}", path.display())))?;
        if width < 2 || height < 2 || width > MAX_SIDE || height > MAX_SIDE {
            return Err(Diag::new(
                span,
                format!("height_field: the image is {width}×{height}; it must be 2×2 to {MAX_SIDE}×{MAX_SIDE} pixels"),
            ));
        }
        let field = HeightFieldDesc {
            file: path.display().to_string(),
            format: format.to_string(),
            width: width as u32,
            height: height as u32,
            heights,
        };
        Ok(ShapeDesc::HeightField { field: Arc::new(field), smooth, water_level })
    }
}

impl Lowerer<'_> {
    /// `height_field { function W, H { F } }` (POV-Ray 3.4.7.1.12.2, "function image"): F on
    /// the unit square of the x-y plane, column i at x = i / (W − 1) and row j (row 0 the top,
    /// at z = 1) at y = j / (H − 1), so y runs against the field's z. A pigment function gives
    /// its gray. A value outside [0, 1] wraps as a pattern does, except that whole numbers
    /// above 0 are 1 (measured with `trace` on 3×3 fields in POV-Ray 3.7: 2x − 0.5 is 0.5
    /// everywhere, 2x is 0, 1, 1), then quantised to 16 bits as POV-Ray's image is.
    pub(crate) fn function_height_field(
        &mut self,
        f: &crate::function::Function,
        (w, h): (f64, f64),
        span: Span,
        smooth: bool,
        water_level: f64,
    ) -> PResult<ShapeDesc> {
        let whole = |v: f64| v.fract() == 0.0 && (2.0..=MAX_SIDE as f64).contains(&v);
        if !whole(w) || !whole(h) {
            return Err(Diag::new(
                span,
                format!("height_field function: the size {w} × {h} must be whole numbers from 2 to {MAX_SIDE}"),
            ));
        }
        let (width, height) = (w as usize, h as usize);
        let program = f.compile();
        let mut heights = Vec::with_capacity(width * height);
        for j in 0..height {
            let y = j as f64 / (height - 1) as f64;
            for i in 0..width {
                let x = i as f64 / (width - 1) as f64;
                let v = match &f.color {
                    Some(shade) => shade.value(crate::function::Channel::Gray, &[x, y, 0.0]),
                    None => program.eval(&[x, y, 0.0]),
                };
                heights.push(((function_height(v) * 65535.0).round() / 65535.0) as f32);
            }
        }
        let field = HeightFieldDesc {
            file: String::new(),
            format: "function".to_string(),
            width: width as u32,
            height: height as u32,
            heights,
        };
        Ok(ShapeDesc::HeightField { field: Arc::new(field), smooth, water_level })
    }
}

/// A function image's value as a height in [0, 1] (see `function_height_field`).
fn function_height(v: f64) -> f64 {
    if !v.is_finite() {
        return 0.0;
    }
    if (0.0..=1.0).contains(&v) {
        return v;
    }
    let f = v - v.floor();
    if f == 0.0 {
        1.0
    } else {
        f
    }
}

type Heights = (usize, usize, Vec<f32>);

/// A colour pixel's height: red is the high byte, green the low one.
fn red_green(r: u8, g: u8) -> f32 {
    ((r as u32) << 8 | g as u32) as f32 / 65535.0
}

fn png_heights(bytes: &[u8]) -> Result<Heights, String> {
    let mut dec = png::Decoder::new(std::io::Cursor::new(bytes));
    // Palette images keep their indices (POV-Ray uses the index, not the colour).
    dec.set_transformations(png::Transformations::IDENTITY);
    let mut reader = dec.read_info().map_err(|e| e.to_string())?;
    let (w, h) = (reader.info().width as usize, reader.info().height as usize);
    if w > MAX_SIDE || h > MAX_SIDE {
        return Ok((w, h, Vec::new()));
    }
    let mut buf = vec![0; reader.output_buffer_size()];
    let frame = reader.next_frame(&mut buf).map_err(|e| e.to_string())?;
    let (color, depth) = (frame.color_type, frame.bit_depth as usize);
    let line = frame.line_size;
    let channels = color.samples();
    let max = ((1u32 << depth) - 1) as f32;
    let sample = |row: &[u8], i: usize| -> u32 {
        match depth {
            16 => u16::from_be_bytes([row[2 * i], row[2 * i + 1]]) as u32,
            8 => row[i] as u32,
            d => {
                let bit = i * d;
                ((row[bit / 8] >> (8 - d - bit % 8)) as u32) & ((1 << d) - 1)
            }
        }
    };
    let mut out = Vec::with_capacity(w * h);
    for y in 0..h {
        let row = &buf[y * line..(y + 1) * line];
        for x in 0..w {
            let v = match color {
                png::ColorType::Grayscale | png::ColorType::GrayscaleAlpha => sample(row, x * channels) as f32 / max,
                png::ColorType::Indexed => sample(row, x) as f32 / 255.0,
                // 16-bit colour: red carries the height on its own.
                _ if depth == 16 => sample(row, x * channels) as f32 / 65535.0,
                _ => red_green(row[x * channels], row[x * channels + 1]),
            };
            out.push(v.min(1.0));
        }
    }
    Ok((w, h, out))
}

/// JPEG: a grey image's value; a colour one's red and green as one 16-bit height, as 8-bit
/// colour PNG and TGA are read (a grey picture stored as RGB gives its grey either way).
fn jpeg_heights(bytes: &[u8]) -> Result<Heights, String> {
    let img = crate::image_file::read_image("jpeg", bytes, MAX_SIDE)?;
    let n = img.channels.count();
    let heights = img
        .samples
        .chunks_exact(n)
        .map(|s| if n == 1 { s[0] as f32 / img.max as f32 } else { red_green(s[0] as u8, s[1] as u8) })
        .collect();
    Ok((img.width, img.height, heights))
}

/// GIF: a pixel's palette index over 255 (POV-Ray 3.4.5.1.6: entry 0 is height 0, entry 255
/// height 1, whatever their colours).
fn gif_heights(bytes: &[u8]) -> Result<Heights, String> {
    let img = crate::image_file::read_gif(bytes, MAX_SIDE)?;
    Ok((img.width, img.height, img.indices.iter().map(|&i| i as f32 / 255.0).collect()))
}

/// POT (Fractint's 16-bit continuous potential): a GIF twice as wide as the field, whose left
/// half holds each height's high byte and right half its low byte.
fn pot_heights(bytes: &[u8]) -> Result<Heights, String> {
    let img = crate::image_file::read_gif(bytes, 2 * MAX_SIDE)?;
    if img.width % 2 != 0 {
        return Err(format!("a POT file is twice as wide as its field; this one is {} pixels wide", img.width));
    }
    let w = img.width / 2;
    let mut out = Vec::with_capacity(w * img.height);
    for row in img.indices.chunks_exact(img.width) {
        let (high, low) = row.split_at(w);
        out.extend(high.iter().zip(low).map(|(&h, &l)| red_green(h, l)));
    }
    Ok((w, img.height, out))
}

/// PGM (P2, P5) and PPM (P3, P6).
fn pnm_heights(bytes: &[u8]) -> Result<Heights, String> {
    let magic = bytes.get(..2).ok_or("empty file")?;
    let (ascii, color) = match magic {
        b"P2" => (true, false),
        b"P5" => (false, false),
        b"P3" => (true, true),
        b"P6" => (false, true),
        _ => return Err("not a PGM or PPM file (P2, P3, P5 or P6)".into()),
    };
    // Header: width, height, maxval, whitespace- and comment-separated.
    let mut pos = 2;
    let mut header = [0usize; 3];
    for slot in &mut header {
        *slot = pnm_number(bytes, &mut pos).ok_or("truncated header")?;
    }
    let [w, h, maxval] = header;
    if maxval == 0 || maxval > 65535 {
        return Err(format!("maximum value {maxval} must lie in 1..65535"));
    }
    if w > MAX_SIDE || h > MAX_SIDE {
        return Ok((w, h, Vec::new()));
    }
    let channels = if color { 3 } else { 1 };
    let n = w * h * channels;
    let samples: Vec<u32> = if ascii {
        (0..n)
            .map(|_| pnm_number(bytes, &mut pos).map(|v| v as u32).ok_or("too few pixels"))
            .collect::<Result<_, _>>()?
    } else {
        pos += 1;
        let size = if maxval > 255 { 2 } else { 1 };
        let data = bytes.get(pos..pos + n * size).ok_or("too few pixels")?;
        if size == 2 {
            data.chunks_exact(2).map(|c| u16::from_be_bytes([c[0], c[1]]) as u32).collect()
        } else {
            data.iter().map(|&b| b as u32).collect()
        }
    };
    let heights = samples
        .chunks_exact(channels)
        .map(|p| match (color, maxval) {
            (true, m) if m <= 255 => red_green(p[0] as u8, p[1] as u8),
            (true, m) => p[0] as f32 / m as f32,
            (false, m) => (p[0] as f32 / m as f32).min(1.0),
        })
        .collect();
    Ok((w, h, heights))
}

/// TGA: colour-mapped (1, 9: the index), true colour (2, 10: red and green) and grey (3, 11),
/// uncompressed or run-length encoded.
fn tga_heights(bytes: &[u8]) -> Result<Heights, String> {
    let head = bytes.get(..18).ok_or("truncated header")?;
    let (id_len, map_type, kind) = (head[0] as usize, head[1], head[2]);
    let map_len = u16::from_le_bytes([head[5], head[6]]) as usize;
    let map_bits = head[7] as usize;
    let (w, h) = (u16::from_le_bytes([head[12], head[13]]) as usize, u16::from_le_bytes([head[14], head[15]]) as usize);
    let bits = head[16] as usize;
    let top_down = head[17] & 0x20 != 0;
    if !matches!(kind, 1 | 2 | 3 | 9 | 10 | 11) {
        return Err(format!("TGA image type {kind} is not read (1, 2, 3, 9, 10, 11 are)"));
    }
    if w > MAX_SIDE || h > MAX_SIDE {
        return Ok((w, h, Vec::new()));
    }
    let size = bits.div_ceil(8);
    if size == 0 || (kind & 3 == 2 && size < 3) {
        return Err(format!("{bits} bits per pixel is not read"));
    }
    let pos = 18 + id_len + if map_type == 1 { map_len * map_bits.div_ceil(8) } else { 0 };
    let pixels = tga_pixels(bytes, pos, w * h * size, size, kind >= 9)?;
    let mut heights = vec![0.0; w * h];
    for (i, p) in pixels.chunks_exact(size).enumerate() {
        let (x, y) = (i % w, i / w);
        // Rows are stored bottom-up unless the descriptor says otherwise; heights are top-down.
        let row = if top_down { y } else { h - 1 - y };
        heights[row * w + x] = match kind & 3 {
            1 => p[0] as f32 / 255.0,
            2 => red_green(p[2], p[1]),
            _ => p[0] as f32 / 255.0,
        };
    }
    Ok((w, h, heights))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn pgm_ascii_and_binary() {
        let (w, h, v) = pnm_heights(b"P2\n# c\n3 2\n255\n255 0 0\n0 0 128\n").unwrap();
        assert_eq!((w, h), (3, 2));
        assert_eq!(v[0], 1.0);
        assert_eq!(v[5], 128.0 / 255.0);
        let (_, _, b) = pnm_heights(b"P5 2 2 255\n\x00\xff\x80\x00").unwrap();
        assert_eq!(b, vec![0.0, 1.0, 128.0 / 255.0, 0.0]);
        assert!(pnm_heights(b"P5 2 2 255\n\x00").is_err());
    }

    #[test]
    fn ppm_red_and_green_are_one_sixteen_bit_height() {
        let (_, _, v) = pnm_heights(b"P3 2 1 255 1 2 3 255 255 0").unwrap();
        assert_eq!(v[0], 258.0 / 65535.0);
        assert_eq!(v[1], 1.0);
    }

    #[test]
    fn tga_uncompressed_and_rle_agree() {
        let mut raw = vec![0u8, 0, 3, 0, 0, 0, 0, 0, 0, 0, 0, 0, 2, 0, 2, 0, 8, 0x20];
        let mut rle = raw.clone();
        rle[2] = 11;
        raw.extend([10, 20, 30, 40]);
        rle.extend([0x81, 10, 0x01, 30, 40]);
        let a = tga_heights(&raw).unwrap();
        let b = tga_heights(&rle).unwrap();
        assert_eq!(a.2[0], 10.0 / 255.0);
        assert_eq!(b.2, vec![10.0 / 255.0, 10.0 / 255.0, 30.0 / 255.0, 40.0 / 255.0]);
    }
}
