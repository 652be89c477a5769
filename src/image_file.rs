//! Image files that scenes name (`height_field`, `image_map`, `bump_map`, `image_pattern`),
//! decoded into plain pixel arrays: what a pixel means (a height, a colour) is left to the
//! caller. GIF through the `gif` crate: indices and palette as stored, the first frame placed on
//! its logical screen. `read_image` decodes PNG (1-16 bit grey, grey+alpha, RGB, RGBA,
//! palette with tRNS), GIF, PGM/PPM (P2, P3, P5, P6), TGA (colour-mapped, true colour 16/24/32
//! bit, grey; uncompressed and RLE) and JPEG (grey, RGB, CMYK; through `jpeg-decoder`) into one
//! `Image`; IFF, TIFF, BMP, EXR and HDR are refused by name. The height-field readers in `pov::lower::height_field` keep their own
//! 16-bit red/green conventions.

use std::io::Cursor;

/// A palette image: one index per pixel, rows top to bottom.
#[derive(Clone, Debug, PartialEq)]
pub struct IndexedImage {
    pub width: usize,
    pub height: usize,
    pub indices: Vec<u8>,
    /// RGB entries (the global palette, or the first frame's local one).
    pub palette: Vec<[u8; 3]>,
}

/// Decodes a GIF's first frame onto its logical screen (pixels the frame does not cover are
/// index 0). Images wider or taller than `max_side` are refused before their pixels are read.
pub fn read_gif(bytes: &[u8], max_side: usize) -> Result<IndexedImage, String> {
    let mut options = gif::DecodeOptions::new();
    options.set_color_output(gif::ColorOutput::Indexed);
    let mut decoder = options.read_info(Cursor::new(bytes)).map_err(|e| format!("not a readable GIF: {e}"))?;
    let (width, height) = (decoder.width() as usize, decoder.height() as usize);
    if width > max_side || height > max_side {
        return Err(format!("the image is {width}×{height}; at most {max_side}×{max_side} is read"));
    }
    let global: Option<Vec<u8>> = decoder.global_palette().map(<[u8]>::to_vec);
    let frame =
        decoder.read_next_frame().map_err(|e| format!("not a readable GIF: {e}"))?.ok_or("the GIF holds no image")?;
    let palette_bytes = frame.palette.as_deref().or(global.as_deref()).unwrap_or(&[]);
    let palette = palette_bytes.chunks_exact(3).map(|c| [c[0], c[1], c[2]]).collect();
    let mut indices = vec![0u8; width * height];
    let (left, top) = (frame.left as usize, frame.top as usize);
    let (fw, fh) = (frame.width as usize, frame.height as usize);
    for y in 0..fh.min(height.saturating_sub(top)) {
        for x in 0..fw.min(width.saturating_sub(left)) {
            indices[(top + y) * width + left + x] = frame.buffer.get(y * fw + x).copied().unwrap_or(0);
        }
    }
    Ok(IndexedImage { width, height, indices, palette })
}

/// What one pixel's samples are.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Channels {
    Grey,
    GreyAlpha,
    Rgb,
    Rgba,
    /// One palette index per pixel (`Image::palette`).
    Indexed,
}

impl Channels {
    pub fn count(self) -> usize {
        match self {
            Channels::Grey | Channels::Indexed => 1,
            Channels::GreyAlpha => 2,
            Channels::Rgb => 3,
            Channels::Rgba => 4,
        }
    }
}

/// A decoded image, rows top to bottom, samples as stored (no gamma applied).
#[derive(Clone, Debug, PartialEq)]
pub struct Image {
    pub width: usize,
    pub height: usize,
    pub channels: Channels,
    /// The largest sample value (255 for 8 bits, 65535 for 16, a PNM's maxval).
    pub max: u32,
    /// `channels.count()` samples per pixel.
    pub samples: Vec<u16>,
    /// RGBA entries of a palette image (alpha 255 where the file gives none).
    pub palette: Vec<[u8; 4]>,
}

impl Image {
    /// Pixel (x, y)'s colour and alpha in [0, 1] as stored; a palette image's entry colour.
    pub fn rgba(&self, x: usize, y: usize) -> [f32; 4] {
        let n = self.channels.count();
        let s = &self.samples[(y * self.width + x) * n..][..n];
        let m = self.max as f32;
        match self.channels {
            Channels::Grey => [s[0] as f32 / m, s[0] as f32 / m, s[0] as f32 / m, 1.0],
            Channels::GreyAlpha => [s[0] as f32 / m, s[0] as f32 / m, s[0] as f32 / m, s[1] as f32 / m],
            Channels::Rgb => [s[0] as f32 / m, s[1] as f32 / m, s[2] as f32 / m, 1.0],
            Channels::Rgba => [s[0] as f32 / m, s[1] as f32 / m, s[2] as f32 / m, s[3] as f32 / m],
            Channels::Indexed => {
                let c = self.palette.get(s[0] as usize).copied().unwrap_or([0, 0, 0, 255]);
                c.map(|v| v as f32 / 255.0)
            }
        }
    }

    /// A palette image's index at (x, y); `None` for other images.
    pub fn index(&self, x: usize, y: usize) -> Option<usize> {
        (self.channels == Channels::Indexed).then(|| self.samples[y * self.width + x] as usize)
    }
}

/// The image types POV-Ray names, and whether `read_image` reads them.
pub const READ_TYPES: &[&str] = &["png", "gif", "ppm", "pgm", "tga", "jpeg", "sys"];

/// The image type a file name's extension names (for blocks that give no type keyword).
pub fn type_from_extension(name: &str) -> Option<&'static str> {
    let ext = std::path::Path::new(name).extension()?.to_str()?.to_ascii_lowercase();
    Some(match ext.as_str() {
        "png" => "png",
        "gif" => "gif",
        "tga" => "tga",
        "ppm" => "ppm",
        "pgm" => "pgm",
        "iff" => "iff",
        "jpg" | "jpeg" => "jpeg",
        "tif" | "tiff" => "tiff",
        "bmp" => "bmp",
        "exr" => "exr",
        "hdr" => "hdr",
        _ => return None,
    })
}

/// Decodes `bytes` as the POV-Ray image type `format` (`sys`: whichever of the types read the
/// bytes are). Images wider or taller than `max_side` are refused.
pub fn read_image(format: &str, bytes: &[u8], max_side: usize) -> Result<Image, String> {
    let format = if format == "sys" { sniff(bytes).unwrap_or("sys") } else { format };
    let img = match format {
        "png" => read_png(bytes, max_side)?,
        "gif" => {
            let g = read_gif(bytes, max_side)?;
            Image {
                width: g.width,
                height: g.height,
                channels: Channels::Indexed,
                max: 255,
                samples: g.indices.iter().map(|&i| i as u16).collect(),
                palette: g.palette.iter().map(|c| [c[0], c[1], c[2], 255]).collect(),
            }
        }
        "ppm" | "pgm" => read_pnm(bytes, max_side)?,
        "tga" => read_tga(bytes, max_side)?,
        "jpeg" => read_jpeg(bytes, max_side)?,
        "iff" | "tiff" | "bmp" | "exr" | "hdr" => {
            return Err(format!("{format} images are not read (png, gif, ppm, pgm, tga and jpeg are)"))
        }
        other => return Err(format!("unknown image type `{other}` (png, gif, ppm, pgm, tga and jpeg are read)")),
    };
    if img.width == 0 || img.height == 0 {
        return Err("the image has no pixels".into());
    }
    Ok(img)
}

/// The type the file's first bytes say it is.
fn sniff(bytes: &[u8]) -> Option<&'static str> {
    Some(match bytes {
        [0x89, b'P', b'N', b'G', ..] => "png",
        [b'G', b'I', b'F', ..] => "gif",
        [b'P', b'2' | b'5', ..] => "pgm",
        [b'P', b'3' | b'6', ..] => "ppm",
        [0xff, 0xd8, ..] => "jpeg",
        [b'I', b'I', 42, 0, ..] | [b'M', b'M', 0, 42, ..] => "tiff",
        [b'B', b'M', ..] => "bmp",
        [b'F', b'O', b'R', b'M', ..] => "iff",
        _ if bytes.len() >= 18 && matches!(bytes[2], 1 | 2 | 3 | 9 | 10 | 11) => "tga",
        _ => return None,
    })
}

fn too_big(w: usize, h: usize, max_side: usize) -> Result<(), String> {
    if w > max_side || h > max_side {
        return Err(format!("the image is {w}×{h}; at most {max_side}×{max_side} is read"));
    }
    Ok(())
}

fn read_png(bytes: &[u8], max_side: usize) -> Result<Image, String> {
    let mut dec = png::Decoder::new(Cursor::new(bytes));
    // Palette images keep their indices (POV-Ray's `use_index`, `filter N`).
    dec.set_transformations(png::Transformations::IDENTITY);
    let mut reader = dec.read_info().map_err(|e| format!("not a readable PNG: {e}"))?;
    let (w, h) = (reader.info().width as usize, reader.info().height as usize);
    too_big(w, h, max_side)?;
    let mut palette: Vec<[u8; 4]> = match &reader.info().palette {
        Some(p) => p.chunks_exact(3).map(|c| [c[0], c[1], c[2], 255]).collect(),
        None => Vec::new(),
    };
    if let Some(trns) = &reader.info().trns {
        for (entry, &a) in palette.iter_mut().zip(trns.iter()) {
            entry[3] = a;
        }
    }
    let mut buf = vec![0; reader.output_buffer_size()];
    let frame = reader.next_frame(&mut buf).map_err(|e| format!("not a readable PNG: {e}"))?;
    let (color, depth, line) = (frame.color_type, frame.bit_depth as usize, frame.line_size);
    let channels = match color {
        png::ColorType::Grayscale => Channels::Grey,
        png::ColorType::GrayscaleAlpha => Channels::GreyAlpha,
        png::ColorType::Rgb => Channels::Rgb,
        png::ColorType::Rgba => Channels::Rgba,
        png::ColorType::Indexed => Channels::Indexed,
    };
    let n = channels.count();
    let sample = |row: &[u8], i: usize| -> u16 {
        match depth {
            16 => u16::from_be_bytes([row[2 * i], row[2 * i + 1]]),
            8 => row[i] as u16,
            d => {
                let bit = i * d;
                ((row[bit / 8] >> (8 - d - bit % 8)) as u16) & ((1 << d) - 1)
            }
        }
    };
    let mut samples = Vec::with_capacity(w * h * n);
    for y in 0..h {
        let row = buf.get(y * line..(y + 1) * line).ok_or("truncated PNG")?;
        samples.extend((0..w * n).map(|i| sample(row, i)));
    }
    let max = if channels == Channels::Indexed { 255 } else { (1u32 << depth) - 1 };
    Ok(Image { width: w, height: h, channels, max, samples, palette })
}

/// JPEG: 8-bit grey or RGB (CMYK converted to RGB, 16-bit lossless grey kept at 16 bits).
fn read_jpeg(bytes: &[u8], max_side: usize) -> Result<Image, String> {
    let mut dec = jpeg_decoder::Decoder::new(Cursor::new(bytes));
    dec.read_info().map_err(|e| format!("not a readable JPEG: {e}"))?;
    let info = dec.info().ok_or("not a readable JPEG: no frame header")?;
    let (w, h) = (info.width as usize, info.height as usize);
    too_big(w, h, max_side)?;
    let pixels = dec.decode().map_err(|e| format!("not a readable JPEG: {e}"))?;
    let (channels, max, samples): (Channels, u32, Vec<u16>) = match info.pixel_format {
        jpeg_decoder::PixelFormat::L8 => (Channels::Grey, 255, pixels.iter().map(|&v| v as u16).collect()),
        jpeg_decoder::PixelFormat::L16 => {
            (Channels::Grey, 65535, pixels.chunks_exact(2).map(|b| u16::from_be_bytes([b[0], b[1]])).collect())
        }
        jpeg_decoder::PixelFormat::RGB24 => (Channels::Rgb, 255, pixels.iter().map(|&v| v as u16).collect()),
        // Adobe's CMYK JPEGs store inverted inks; the decoder gives them as stored.
        jpeg_decoder::PixelFormat::CMYK32 => {
            let rgb = pixels.chunks_exact(4).flat_map(|p| {
                let k = 255 - p[3] as u16;
                [0, 1, 2].map(|i| (255 - p[i] as u16) * k / 255)
            });
            (Channels::Rgb, 255, rgb.map(|v| 255 - v).collect())
        }
    };
    if samples.len() != w * h * channels.count() {
        return Err("truncated JPEG".into());
    }
    Ok(Image { width: w, height: h, channels, max, samples, palette: Vec::new() })
}

/// PGM (P2, P5) and PPM (P3, P6), 8 or 16 bits.
fn read_pnm(bytes: &[u8], max_side: usize) -> Result<Image, String> {
    let (ascii, color) = match bytes.get(..2) {
        Some(b"P2") => (true, false),
        Some(b"P5") => (false, false),
        Some(b"P3") => (true, true),
        Some(b"P6") => (false, true),
        _ => return Err("not a PGM or PPM file (P2, P3, P5 or P6)".into()),
    };
    let mut pos = 2;
    let mut header = [0usize; 3];
    for slot in &mut header {
        *slot = pnm_number(bytes, &mut pos).ok_or("truncated header")?;
    }
    let [w, h, maxval] = header;
    if maxval == 0 || maxval > 65535 {
        return Err(format!("maximum value {maxval} must lie in 1..65535"));
    }
    too_big(w, h, max_side)?;
    let channels = if color { Channels::Rgb } else { Channels::Grey };
    let n = w * h * channels.count();
    let samples: Vec<u16> = if ascii {
        (0..n)
            .map(|_| pnm_number(bytes, &mut pos).map(|v| v.min(maxval) as u16).ok_or("too few pixels"))
            .collect::<Result<_, _>>()?
    } else {
        pos += 1;
        let size = if maxval > 255 { 2 } else { 1 };
        let data = bytes.get(pos..pos + n * size).ok_or("too few pixels")?;
        if size == 2 {
            data.chunks_exact(2).map(|c| u16::from_be_bytes([c[0], c[1]])).collect()
        } else {
            data.iter().map(|&b| b as u16).collect()
        }
    };
    Ok(Image { width: w, height: h, channels, max: maxval as u32, samples, palette: Vec::new() })
}

/// The next decimal number of a PNM header or ASCII body, skipping whitespace and `#` comments.
pub(crate) fn pnm_number(bytes: &[u8], pos: &mut usize) -> Option<usize> {
    loop {
        match bytes.get(*pos)? {
            b'#' => {
                while *bytes.get(*pos)? != b'\n' {
                    *pos += 1;
                }
            }
            c if c.is_ascii_whitespace() => *pos += 1,
            _ => break,
        }
    }
    let start = *pos;
    while bytes.get(*pos).is_some_and(u8::is_ascii_digit) {
        *pos += 1;
    }
    std::str::from_utf8(&bytes[start..*pos]).ok()?.parse().ok()
}

/// TGA: colour-mapped (1, 9), true colour (2, 10: 16, 24 or 32 bits) and grey (3, 11),
/// uncompressed or run-length encoded, rows bottom-up unless the descriptor says otherwise.
fn read_tga(bytes: &[u8], max_side: usize) -> Result<Image, String> {
    let head = bytes.get(..18).ok_or("truncated TGA header")?;
    let (id_len, cmap_type, kind) = (head[0] as usize, head[1], head[2]);
    let cmap_first = u16::from_le_bytes([head[3], head[4]]) as usize;
    let cmap_len = u16::from_le_bytes([head[5], head[6]]) as usize;
    let cmap_bits = head[7] as usize;
    let (w, h) = (u16::from_le_bytes([head[12], head[13]]) as usize, u16::from_le_bytes([head[14], head[15]]) as usize);
    let bits = head[16] as usize;
    let top_down = head[17] & 0x20 != 0;
    if !matches!(kind, 1 | 2 | 3 | 9 | 10 | 11) {
        return Err(format!("TGA image type {kind} is not read (1, 2, 3, 9, 10, 11 are)"));
    }
    too_big(w, h, max_side)?;
    let size = bits.div_ceil(8);
    if !(1..=4).contains(&size) || (kind & 3 == 2 && size < 2) {
        return Err(format!("TGA: {bits} bits per pixel is not read"));
    }
    // 16-bit entries are 5-5-5 (+1) little-endian; 24 and 32 are BGR(A).
    let bgra = |p: &[u8]| -> [u8; 4] {
        match p.len() {
            2 => {
                let v = u16::from_le_bytes([p[0], p[1]]);
                let c = |s: u16| (((v >> s) & 31) as u32 * 255 / 31) as u8;
                [c(10), c(5), c(0), 255]
            }
            3 => [p[2], p[1], p[0], 255],
            4 => [p[2], p[1], p[0], p[3]],
            _ => [p[0], p[0], p[0], 255],
        }
    };
    let mut pos = 18 + id_len;
    let mut palette = Vec::new();
    if cmap_type == 1 {
        let esize = cmap_bits.div_ceil(8).max(1);
        let data = bytes.get(pos..pos + cmap_len * esize).ok_or("truncated TGA colour map")?;
        palette = vec![[0, 0, 0, 255]; cmap_first];
        palette.extend(data.chunks_exact(esize).map(bgra));
        pos += cmap_len * esize;
    }
    let pixels = tga_pixels(bytes, pos, w * h * size, size, kind >= 9)?;
    let channels = match kind & 3 {
        1 => Channels::Indexed,
        3 => Channels::Grey,
        _ if size == 4 => Channels::Rgba,
        _ => Channels::Rgb,
    };
    let n = channels.count();
    let mut samples = vec![0u16; w * h * n];
    for (i, p) in pixels.chunks_exact(size).enumerate() {
        let (x, y) = (i % w, i / w);
        let row = if top_down { y } else { h - 1 - y };
        let out = &mut samples[(row * w + x) * n..][..n];
        match channels {
            Channels::Indexed => out[0] = if size == 2 { u16::from_le_bytes([p[0], p[1]]) } else { p[0] as u16 },
            Channels::Grey => out[0] = p[0] as u16,
            _ => {
                let c = bgra(p);
                for (o, v) in out.iter_mut().zip(c) {
                    *o = v as u16;
                }
            }
        }
    }
    Ok(Image { width: w, height: h, channels, max: 255, samples, palette })
}

/// A TGA image's `total` bytes of pixels (`size` bytes each) from `pos`: as stored, or
/// run-length decoded (`rle`, types 9–11). Height fields read 16-bit values from these too.
pub fn tga_pixels(bytes: &[u8], mut pos: usize, total: usize, size: usize, rle: bool) -> Result<Vec<u8>, String> {
    let mut pixels = Vec::with_capacity(total);
    while pixels.len() < total {
        if !rle {
            let take = total - pixels.len();
            pixels.extend_from_slice(bytes.get(pos..pos + take).ok_or("too few pixels")?);
            pos += take;
        } else {
            let packet = *bytes.get(pos).ok_or("too few pixels")? as usize;
            pos += 1;
            let count = (packet & 0x7f) + 1;
            if packet & 0x80 != 0 {
                let p = bytes.get(pos..pos + size).ok_or("too few pixels")?;
                pos += size;
                for _ in 0..count {
                    pixels.extend_from_slice(p);
                }
            } else {
                pixels.extend_from_slice(bytes.get(pos..pos + count * size).ok_or("too few pixels")?);
                pos += count * size;
            }
        }
    }
    pixels.truncate(total);
    Ok(pixels)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A 3×2 GIF87a with a 4-entry global palette and indices 0 1 2 / 3 2 1, hand-assembled:
    /// minimum code size 2, codes (3 bits): clear 4, 0, 1, 2, 3, 2, 1, end 5.
    pub(crate) fn tiny_gif() -> Vec<u8> {
        let mut g = b"GIF87a".to_vec();
        g.extend([3, 0, 2, 0, 0b1000_0001, 0, 0]);
        g.extend([0, 0, 0, 255, 0, 0, 0, 255, 0, 0, 0, 255]);
        g.extend([b',', 0, 0, 0, 0, 3, 0, 2, 0, 0]);
        // Codes LSB first, 3 bits wide until the table's entry 7 is made (by the third data
        // code: the first adds nothing, each later one an entry from 6 up), then 4 bits.
        let codes: [(u32, u32); 8] = [(4, 3), (0, 3), (1, 3), (2, 3), (3, 4), (2, 4), (1, 4), (5, 4)];
        let (mut acc, mut bits, mut data) = (0u32, 0u32, Vec::new());
        for (code, width) in codes {
            acc |= code << bits;
            bits += width;
            while bits >= 8 {
                data.push(acc as u8);
                acc >>= 8;
                bits -= 8;
            }
        }
        if bits > 0 {
            data.push(acc as u8);
        }
        g.push(2);
        g.push(data.len() as u8);
        g.extend(&data);
        g.extend([0, b';']);
        g
    }

    #[test]
    fn a_hand_made_gif_decodes_to_its_indices_and_palette() {
        let img = read_gif(&tiny_gif(), 16).unwrap();
        assert_eq!((img.width, img.height), (3, 2));
        assert_eq!(img.indices, vec![0, 1, 2, 3, 2, 1]);
        assert_eq!(img.palette[1], [255, 0, 0]);
    }

    #[test]
    fn bad_and_oversized_gifs_are_errors() {
        assert!(read_gif(b"GIF89a", 16).is_err());
        assert!(read_gif(b"\x89PNG\r\n", 16).is_err());
        assert!(read_gif(&tiny_gif(), 2).unwrap_err().contains("at most 2"));
    }

    #[test]
    fn every_read_type_decodes_the_same_pixels() {
        // 2×2: red, green / blue, white.
        let px = [[255u8, 0, 0], [0, 255, 0], [0, 0, 255], [255, 255, 255]];
        let mut ppm = b"P6\n# c\n2 2\n255\n".to_vec();
        px.iter().for_each(|p| ppm.extend(p));
        let ppm3 = b"P3 2 2 255 255 0 0 0 255 0 0 0 255 255 255 255".to_vec();
        // TGA type 2, 24 bits, bottom-up rows, BGR; and the same RLE (type 10).
        let mut tga = vec![0, 0, 2, 0, 0, 0, 0, 0, 0, 0, 0, 0, 2, 0, 2, 0, 24, 0];
        for p in [px[2], px[3], px[0], px[1]] {
            tga.extend([p[2], p[1], p[0]]);
        }
        let mut rle = vec![0, 0, 10, 0, 0, 0, 0, 0, 0, 0, 0, 0, 2, 0, 2, 0, 24, 0x20];
        rle.push(3);
        for p in px {
            rle.extend([p[2], p[1], p[0]]);
        }
        for (format, bytes) in [("ppm", ppm.clone()), ("ppm", ppm3), ("tga", tga), ("tga", rle), ("sys", ppm)] {
            let img = read_image(format, &bytes, 16).unwrap_or_else(|e| panic!("{format}: {e}"));
            assert_eq!((img.width, img.height), (2, 2));
            assert_eq!(img.rgba(0, 0), [1.0, 0.0, 0.0, 1.0], "{format}");
            assert_eq!(img.rgba(1, 0), [0.0, 1.0, 0.0, 1.0], "{format}");
            assert_eq!(img.rgba(0, 1), [0.0, 0.0, 1.0, 1.0], "{format}");
        }
        let pgm = read_image("pgm", b"P5 2 1 65535\n\xff\xff\x80\x00", 16).unwrap();
        assert_eq!(pgm.rgba(0, 0)[0], 1.0);
        assert!((pgm.rgba(1, 0)[0] - 0.5).abs() < 1e-4);
        let gif = read_image("gif", &tiny_gif(), 16).unwrap();
        assert_eq!((gif.index(1, 0), gif.rgba(1, 0)), (Some(1), [1.0, 0.0, 0.0, 1.0]));
    }

    /// Made by Pillow (quality 95): 16×8 grey, the left half black and the right white; 16×16
    /// RGB red without chroma subsampling.
    #[test]
    fn jpegs_decode_grey_and_colour_and_refuse_big_ones() {
        let grey = read_image("jpeg", include_bytes!("../tests/reference/images/halves.jpg"), 16).unwrap();
        assert_eq!((grey.width, grey.height, grey.channels), (16, 8, Channels::Grey));
        assert!(grey.rgba(0, 0)[0] < 0.03 && grey.rgba(15, 7)[0] > 0.97, "{:?}", grey.rgba(15, 7));
        let red = include_bytes!("../tests/reference/images/red.jpg");
        let rgb = read_image("sys", red, 16).unwrap();
        assert_eq!(rgb.channels, Channels::Rgb);
        let [r, g, b, a] = rgb.rgba(7, 9);
        assert!(r > 0.97 && g < 0.03 && b < 0.03 && a == 1.0, "{:?}", rgb.rgba(7, 9));
        assert!(read_image("jpeg", red, 15).unwrap_err().contains("at most 15"));
        assert!(read_image("jpeg", &red[..200], 16).is_err());
    }

    #[test]
    fn unread_types_and_bad_bytes_are_errors() {
        assert!(read_image("jpeg", b"\xff\xd8", 16).unwrap_err().contains("not a readable JPEG"));
        assert!(read_image("sys", b"\xff\xd8\xff", 16).unwrap_err().contains("JPEG"));
        assert!(read_image("tiff", b"II*\x00", 16).unwrap_err().contains("tiff images are not read"));
        assert!(read_image("png", b"\x89PNG\r\n", 16).is_err());
        assert!(read_image("ppm", b"P6 2 2 255\n\x00", 16).is_err());
        assert!(read_image("tga", &[0, 0, 2, 0, 0, 0, 0, 0, 0, 0, 0, 0, 2, 0, 2, 0, 24, 0, 1], 16).is_err());
        assert!(read_image("ppm", b"P6 20 20 255\n", 16).unwrap_err().contains("at most"));
    }
}
