//! `text { ttf "font.ttf" "string" thickness, offset }` (or `internal N` for one of POV-Ray's
//! built-in fonts) → glyph outlines (`ShapeDesc::Text`).
//!
//! The font is found as POV-Ray finds it: the name as written, then the scene's folder and the
//! include path (as `#include` searches them). Glyphs come from `ttf-parser`: each outline is
//! quadratic Bézier contours in font units, scaled by 1/em so the em is 1 unit, placed along x
//! by the advance widths (plus the kerning pairs of the font's `kern` table) with `offset`
//! added after each character, as POV-Ray 3.7 places them (measured on its renders).

use glam::{DVec2, DVec3};

use super::Lowerer;
use crate::desc::{ShapeDesc, TextGlyph};
use crate::pov::ast::{Expr, ExprKind};
use crate::pov::source::{Diag, PResult, Span};

/// Collects one glyph's contours as quadratic pieces, in font units.
struct Outline {
    quads: Vec<[DVec2; 3]>,
    start: DVec2,
    at: DVec2,
}

impl Outline {
    fn line(&mut self, to: DVec2) {
        if to != self.at {
            self.quads.push([self.at, 0.5 * (self.at + to), to]);
        }
        self.at = to;
    }
}

impl ttf_parser::OutlineBuilder for Outline {
    fn move_to(&mut self, x: f32, y: f32) {
        self.start = DVec2::new(x as f64, y as f64);
        self.at = self.start;
    }
    fn line_to(&mut self, x: f32, y: f32) {
        self.line(DVec2::new(x as f64, y as f64));
    }
    fn quad_to(&mut self, x1: f32, y1: f32, x: f32, y: f32) {
        let (c, to) = (DVec2::new(x1 as f64, y1 as f64), DVec2::new(x as f64, y as f64));
        self.quads.push([self.at, c, to]);
        self.at = to;
    }
    fn curve_to(&mut self, x1: f32, y1: f32, x2: f32, y2: f32, x: f32, y: f32) {
        // CFF cubics (not in TrueType fonts): two quadratics through the cubic's midpoint.
        let p0 = self.at;
        let (p1, p2, p3) =
            (DVec2::new(x1 as f64, y1 as f64), DVec2::new(x2 as f64, y2 as f64), DVec2::new(x as f64, y as f64));
        // Each half's quadratic control: (3·(c1 + c2) − (start + end)) / 4 of its cubic.
        let mid = 0.125 * (p0 + 3.0 * p1 + 3.0 * p2 + p3);
        let (a1, a2) = (0.5 * (p0 + p1), 0.25 * (p0 + 2.0 * p1 + p2));
        let (b1, b2) = (0.25 * (p1 + 2.0 * p2 + p3), 0.5 * (p2 + p3));
        self.quads.push([p0, 0.25 * (3.0 * (a1 + a2) - p0 - mid), mid]);
        self.quads.push([mid, 0.25 * (3.0 * (b1 + b2) - mid - p3), p3]);
        self.at = p3;
    }
    fn close(&mut self) {
        let start = self.start;
        self.line(start);
    }
}

impl Lowerer<'_> {
    /// `ttf "font" "string" thickness, offset`.
    pub(super) fn text(&mut self, args: &[Expr], span: Span) -> PResult<ShapeDesc> {
        let arg = |i: usize| {
            args.get(i).ok_or_else(|| Diag::new(span, "text needs: ttf \"font.ttf\" \"string\" thickness, offset"))
        };
        let font_expr = arg(1)?;
        let (name, builtin) = match &arg(0)?.kind {
            ExprKind::Ident(w) if w == "ttf" => (self.string(font_expr)?, None),
            ExprKind::Ident(w) if w == "internal" => {
                let n = self.float(font_expr)?;
                let file = internal_font(n);
                (file.to_string(), Some(n))
            }
            _ => {
                return Err(Diag::new(
                    arg(0)?.span,
                    "text needs `ttf` and a font file, or `internal` and a font number, first",
                ))
            }
        };
        let string = self.string(arg(2)?)?;
        let thickness = self.float(arg(3)?)?;
        let offset = self.vec3(arg(4)?)?;
        if thickness == 0.0 {
            return Err(Diag::new(arg(3)?.span, "text thickness must not be 0"));
        }
        // POV-Ray finds a font named without an extension as `.ttf` (`#declare Font="crystal"`
        // in advanced/blocks); a name as written comes first.
        let mut candidates = vec![name.clone()];
        if std::path::Path::new(&name).extension().is_none() {
            candidates.push(format!("{name}.ttf"));
        }
        let found = candidates.iter().find_map(|n| {
            if std::path::Path::new(n).is_file() {
                Some(std::path::PathBuf::from(n))
            } else {
                self.files.data_path(n, false).ok().filter(|p| p.is_file())
            }
        });
        let path = found.ok_or_else(|| {
            let what = match builtin {
                Some(n) => format!("built-in font {n} is POV-Ray's \"{name}\" (package fonts-povray), which was"),
                None => format!("font \"{name}\""),
            };
            Diag::new(
                font_expr.span,
                format!("{what} not found (searched as written, the scene's folder and the include path)"),
            )
        })?;
        let data = std::fs::read(&path)
            .map_err(|e| Diag::new(font_expr.span, format!("cannot read font \"{}\": {e}", path.display())))?;
        let face = ttf_parser::Face::parse(&data, 0)
            .map_err(|e| Diag::new(font_expr.span, format!("\"{}\" is not a TrueType font: {e}", path.display())))?;
        let glyphs = layout(&face, &string, offset);
        Ok(ShapeDesc::Text {
            font: path.display().to_string().into(),
            string,
            thickness,
            offset: Box::new(offset),
            glyphs: glyphs.into(),
        })
    }
}

/// The font file of `text { internal N ... }`. POV-Ray 3.7 builds four fonts in so that its
/// benchmark runs without installed files (the reference's `text` section): 0 povlogo, 1 timrom,
/// 2 cyrvetic, 3 crystal, and any other number is 0. They are the TrueType files POV-Ray ships
/// (Debian's fonts-povray puts them on the include path), so strahl reads those.
fn internal_font(n: f64) -> &'static str {
    const FONTS: [&str; 4] = ["povlogo.ttf", "timrom.ttf", "cyrvetic.ttf", "crystal.ttf"];
    let i = if n >= 0.0 && n < FONTS.len() as f64 { n as usize } else { 0 };
    FONTS[i]
}

/// The glyphs of `string` placed along x, the em scaled to 1.
fn layout(face: &ttf_parser::Face, string: &str, offset: DVec3) -> Vec<TextGlyph> {
    let em = f64::from(face.units_per_em().max(1));
    let mut pen = DVec2::ZERO;
    let mut glyphs = Vec::new();
    let mut previous: Option<ttf_parser::GlyphId> = None;
    for ch in string.chars() {
        let id = face.glyph_index(ch).unwrap_or(ttf_parser::GlyphId(0));
        match previous {
            Some(left) => pen.x += kerning(face, left, id) / em,
            // The first glyph's left side bearing is dropped: its ink starts at x = 0.
            None => pen.x -= f64::from(face.glyph_hor_side_bearing(id).unwrap_or(0)) / em,
        }
        let mut outline = Outline { quads: Vec::new(), start: DVec2::ZERO, at: DVec2::ZERO };
        if face.outline_glyph(id, &mut outline).is_some() && !outline.quads.is_empty() {
            let quads = outline.quads.iter().map(|q| q.map(|p| p / em + pen)).collect();
            glyphs.push(TextGlyph { quads });
        }
        pen.x += f64::from(face.glyph_hor_advance(id).unwrap_or(0)) / em + offset.x;
        pen.y += offset.y;
        previous = Some(id);
    }
    glyphs
}

/// The horizontal kerning between two glyphs in font units (0 without a `kern` pair).
/// Format 0 pairs are scanned, not binary searched: POV-Ray's own fonts (cyrvetic.ttf, and
/// timrom.ttf for `To`) store them unsorted, and POV-Ray finds them.
fn kerning(face: &ttf_parser::Face, left: ttf_parser::GlyphId, right: ttf_parser::GlyphId) -> f64 {
    let Some(kern) = face.tables().kern else { return 0.0 };
    let pair = (u32::from(left.0) << 16) | u32::from(right.0);
    kern.subtables
        .into_iter()
        .filter(|s| s.horizontal && !s.variable && !s.has_cross_stream)
        .find_map(|s| match &s.format {
            ttf_parser::kern::Format::Format0(t) => t.pairs.into_iter().find(|p| p.pair == pair).map(|p| p.value),
            _ => s.glyphs_kerning(left, right),
        })
        .map_or(0.0, f64::from)
}

#[cfg(test)]
mod tests {
    use super::*;

    const FONTS: &str = "/usr/share/povray-3.7/include";

    /// The font, or a printed reason to skip (CI installs fonts-povray).
    fn font(name: &str) -> Option<Vec<u8>> {
        let path = std::path::Path::new(FONTS).join(name);
        match std::fs::read(&path) {
            Ok(d) => Some(d),
            Err(e) => {
                println!("skipped: {} not readable ({e}); install fonts-povray", path.display());
                None
            }
        }
    }

    /// The kern pairs POV-Ray 3.7 applies (its renders of "AV" and "To" are this much
    /// narrower than the advance widths), some stored out of order.
    #[test]
    fn kerning_pairs_of_povrays_fonts() {
        for (name, av, to) in [("timrom.ttf", -187.0, -42.0), ("cyrvetic.ttf", -81.0, -75.0)] {
            let Some(data) = font(name) else { return };
            let face = ttf_parser::Face::parse(&data, 0).expect("font");
            let g = |c| face.glyph_index(c).expect("glyph");
            assert_eq!((kerning(&face, g('A'), g('V')), kerning(&face, g('T'), g('o'))), (av, to), "{name}");
            assert_eq!(kerning(&face, g('I'), g('I')), 0.0);
        }
    }
}
