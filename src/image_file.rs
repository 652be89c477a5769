//! Image files that scenes name (`height_field`, and `image_map` next), decoded into plain
//! pixel arrays: what a pixel means (a height, a colour) is left to the caller. GIF through the
//! `gif` crate: indices and palette as stored, the first frame placed on its logical screen.
//! PNG, PGM/PPM and TGA height readers still live in `pov::lower::height_field`.

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
}
