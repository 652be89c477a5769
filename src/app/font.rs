//! An 8×8 bitmap font for ASCII 32..127, drawn straight into a 0RGB framebuffer.
//!
//! Glyphs are font8x8_basic by Daniel Hepper (public domain), itself from the public-domain IBM
//! VGA fonts. Each glyph is one u64: byte `r` is row `r` (top first), bit `c` is column `c`
//! (leftmost = least significant bit).

/// ASCII 32 (space) through 127.
const GLYPHS: [u64; 96] = [
    0x0000000000000000,
    0x00180018183C3C18,
    0x0000000000003636,
    0x0036367F367F3636, // ' ' '!' '"' '#'
    0x000C1F301E033E0C,
    0x0063660C18336300,
    0x006E333B6E1C361C,
    0x0000000000030606, // '$' '%' '&' "'"
    0x00180C0606060C18,
    0x00060C1818180C06,
    0x0000663CFF3C6600,
    0x00000C0C3F0C0C00, // '(' ')' '*' '+'
    0x060C0C0000000000,
    0x000000003F000000,
    0x000C0C0000000000,
    0x000103060C183060, // ',' '-' '.' '/'
    0x003E676F7B73633E,
    0x003F0C0C0C0C0E0C,
    0x003F33061C30331E,
    0x001E33301C30331E, // '0' '1' '2' '3'
    0x0078307F33363C38,
    0x001E3330301F033F,
    0x001E33331F03061C,
    0x000C0C0C1830333F, // '4' '5' '6' '7'
    0x001E33331E33331E,
    0x000E18303E33331E,
    0x000C0C00000C0C00,
    0x060C0C00000C0C00, // '8' '9' ':' ';'
    0x00180C0603060C18,
    0x00003F00003F0000,
    0x00060C1830180C06,
    0x000C000C1830331E, // '<' '=' '>' '?'
    0x001E037B7B7B633E,
    0x0033333F33331E0C,
    0x003F66663E66663F,
    0x003C66030303663C, // '@' 'A' 'B' 'C'
    0x001F36666666361F,
    0x007F46161E16467F,
    0x000F06161E16467F,
    0x007C66730303663C, // 'D' 'E' 'F' 'G'
    0x003333333F333333,
    0x001E0C0C0C0C0C1E,
    0x001E333330303078,
    0x006766361E366667, // 'H' 'I' 'J' 'K'
    0x007F66460606060F,
    0x0063636B7F7F7763,
    0x006363737B6F6763,
    0x001C36636363361C, // 'L' 'M' 'N' 'O'
    0x000F06063E66663F,
    0x00381E3B3333331E,
    0x006766363E66663F,
    0x001E33380E07331E, // 'P' 'Q' 'R' 'S'
    0x001E0C0C0C0C2D3F,
    0x003F333333333333,
    0x000C1E3333333333,
    0x0063777F6B636363, // 'T' 'U' 'V' 'W'
    0x0063361C1C366363,
    0x001E0C0C1E333333,
    0x007F664C1831637F,
    0x001E06060606061E, // 'X' 'Y' 'Z' '['
    0x00406030180C0603,
    0x001E18181818181E,
    0x0000000063361C08,
    0xFF00000000000000, // '\\' ']' '^' '_'
    0x0000000000180C0C,
    0x006E333E301E0000,
    0x003B66663E060607,
    0x001E3303331E0000, // '`' 'a' 'b' 'c'
    0x006E33333E303038,
    0x001E033F331E0000,
    0x000F06060F06361C,
    0x1F303E33336E0000, // 'd' 'e' 'f' 'g'
    0x006766666E360607,
    0x001E0C0C0C0E000C,
    0x1E33333030300030,
    0x0067361E36660607, // 'h' 'i' 'j' 'k'
    0x001E0C0C0C0C0C0E,
    0x00636B7F7F330000,
    0x00333333331F0000,
    0x001E3333331E0000, // 'l' 'm' 'n' 'o'
    0x0F063E66663B0000,
    0x78303E33336E0000,
    0x000F06666E3B0000,
    0x001F301E033E0000, // 'p' 'q' 'r' 's'
    0x00182C0C0C3E0C08,
    0x006E333333330000,
    0x000C1E3333330000,
    0x00367F7F6B630000, // 't' 'u' 'v' 'w'
    0x0063361C36630000,
    0x1F303E3333330000,
    0x003F260C193F0000,
    0x00380C0C070C0C38, // 'x' 'y' 'z' '{'
    0x0018181800181818,
    0x00070C0C380C0C07,
    0x0000000000003B6E,
    0x0000000000000000, // '|' '}' '~' '\x7f'
];

pub const GLYPH: u32 = 8;

/// The glyph for `c`; anything outside ASCII 32..127 draws as '?'.
pub fn glyph(c: char) -> u64 {
    let i = c as u32;
    if (32..128).contains(&i) {
        GLYPHS[(i - 32) as usize]
    } else {
        GLYPHS[('?' as u32 - 32) as usize]
    }
}

/// A 0RGB framebuffer borrowed for drawing; everything is clipped to it.
pub struct Canvas<'a> {
    pub pixels: &'a mut [u32],
    pub width: u32,
    pub height: u32,
}

impl Canvas<'_> {
    /// Draws `text` with its top-left corner at (x, y), each font pixel `scale`×`scale`.
    pub fn text(&mut self, x: i32, y: i32, text: &str, color: u32, scale: u32) {
        let scale = scale.max(1) as i32;
        for (i, c) in text.chars().enumerate() {
            let g = glyph(c);
            let gx = x + i as i32 * GLYPH as i32 * scale;
            for row in 0..8 {
                let bits = (g >> (row * 8)) as u8;
                for col in 0..8 {
                    if bits & (1 << col) != 0 {
                        self.fill(gx + col * scale, y + row * scale, scale as u32, scale as u32, color);
                    }
                }
            }
        }
    }

    pub fn fill(&mut self, x: i32, y: i32, w: u32, h: u32, color: u32) {
        self.map_rect(x, y, w, h, |_| color);
    }

    /// Darkens a rectangle to `keep`/256 of its brightness, so text over it stays readable.
    pub fn shade(&mut self, x: i32, y: i32, w: u32, h: u32, keep: u32) {
        self.map_rect(x, y, w, h, |p| {
            let ch = |s: u32| (((p >> s) & 0xff) * keep / 256) << s;
            ch(16) | ch(8) | ch(0)
        });
    }

    fn map_rect(&mut self, x: i32, y: i32, w: u32, h: u32, f: impl Fn(u32) -> u32) {
        let x0 = x.clamp(0, self.width as i32) as usize;
        let y0 = y.clamp(0, self.height as i32) as usize;
        let x1 = (x + w as i32).clamp(0, self.width as i32) as usize;
        let y1 = (y + h as i32).clamp(0, self.height as i32) as usize;
        let stride = self.width as usize;
        for row in y0..y1 {
            for p in &mut self.pixels[row * stride + x0..row * stride + x1] {
                *p = f(*p);
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn space_is_blank_and_letters_are_not() {
        assert_eq!(glyph(' '), 0);
        for c in ('!'..='~').filter(|c| *c != ' ') {
            assert_ne!(glyph(c), 0, "{c:?}");
        }
        assert_eq!(glyph('é'), glyph('?'));
    }

    #[test]
    fn drawing_clips_at_every_edge() {
        let mut px = vec![0u32; 20 * 10];
        let mut c = Canvas { pixels: &mut px, width: 20, height: 10 };
        c.text(-5, -5, "Hello", 0xffffff, 2);
        c.text(15, 8, "W", 0xffffff, 3);
        c.shade(-100, -100, 1000, 1000, 128);
        c.fill(19, 9, 5, 5, 0x123456);
        assert_eq!(px[199], 0x123456);
    }

    #[test]
    fn a_glyph_lands_where_asked() {
        let mut px = vec![0u32; 8 * 8];
        Canvas { pixels: &mut px, width: 8, height: 8 }.text(0, 0, "!", 1, 1);
        // '!' row 0 is 0x18: columns 3 and 4.
        assert_eq!(&px[..8], &[0, 0, 0, 1, 1, 0, 0, 0]);
    }
}
