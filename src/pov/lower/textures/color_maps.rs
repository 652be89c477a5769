//! Colour maps → sorted `ColorMapEntry` lists, and the maps POV-Ray gives patterns written
//! without one.

use crate::desc::{Color, ColorMapEntry, PatternKind};
use crate::pov::ast::{ColorMap, ColorMapBody};
use crate::pov::lower::Lowerer;
use crate::pov::source::{Diag, PResult};
use crate::pov::value::Value;

/// POV-Ray 3.7's map for `wood` without a `color_map`: light tan up to 0.6, then dark brown,
/// with a hard edge. Measured by rendering `plane { z, 0 pigment { wood } }` with `ambient 1
/// diffuse 0` and `File_Gamma=1.0`: rings switch colour at radius 0.3 and 0.7, i.e. at 0.6 of
/// the triangle wave, and the colours read back as (170, 80, 51) and (102, 34, 17) / 255.
pub(super) fn default_wood_map() -> Vec<ColorMapEntry> {
    let tan = Color::rgb(0.666, 0.312, 0.2);
    let brown = Color::rgb(0.4, 0.133, 0.066);
    [(0.0, tan), (0.6, tan), (0.6, brown), (1.0, brown)]
        .into_iter()
        .map(|(value, color)| ColorMapEntry { value, color })
        .collect()
}

/// POV-Ray's colours of a list pattern written without them.
pub(super) fn default_list_colors(kind: &PatternKind) -> [Color; 3] {
    match kind {
        // brick: mortar grey, brick red.
        PatternKind::Brick { .. } => [Color::rgb(0.5, 0.5, 0.5), Color::rgb(0.6, 0.15, 0.15), Color::BLACK],
        PatternKind::Hexagon => [Color::rgb(0.0, 0.0, 1.0), Color::rgb(0.0, 1.0, 0.0), Color::rgb(1.0, 0.0, 0.0)],
        _ => [Color::rgb(0.0, 0.0, 1.0), Color::rgb(0.0, 1.0, 0.0), Color::BLACK],
    }
}

/// The map of pattern `name` written without one: black to white, but `bozo`, `marble`,
/// `agate`, `radial` and `mandel` have maps of their own (`spotted` and `bumps`, bozo's noise,
/// do not). Measured with `#debug` on `function { pigment { P } }` beside `function {
/// pattern { P } }` at 3000 points each (mandel at 100000 iterations for its low values):
/// bozo steps white, green, blue, red at 0.4, 0.6, 0.8; marble runs from (0.9, 0.8, 0.8) down
/// by 0.8 per unit in green and blue to 0.9, then black; the others as below (to 1e-3).
pub(super) fn default_pattern_map(name: &str) -> Vec<ColorMapEntry> {
    let entries: &[(f64, [f64; 3])] = match name {
        "bozo" => &[
            (0.0, [1.0, 1.0, 1.0]),
            (0.4, [1.0, 1.0, 1.0]),
            (0.4, [0.0, 1.0, 0.0]),
            (0.6, [0.0, 1.0, 0.0]),
            (0.6, [0.0, 0.0, 1.0]),
            (0.8, [0.0, 0.0, 1.0]),
            (0.8, [1.0, 0.0, 0.0]),
            (1.0, [1.0, 0.0, 0.0]),
        ],
        "marble" => &[(0.0, [0.9, 0.8, 0.8]), (0.9, [0.9, 0.08, 0.08]), (0.9, [0.0; 3]), (1.0, [0.0; 3])],
        "agate" => &[
            (0.0, [1.0, 1.0, 1.0]),
            (0.5, [0.95, 0.75, 0.5]),
            (0.5, [0.9, 0.7, 0.5]),
            (0.6, [0.9, 0.7, 0.4]),
            (0.6, [1.0, 0.7, 0.4]),
            (1.0, [0.6, 0.3, 0.0]),
        ],
        "radial" => &[
            (0.0, [0.0, 1.0, 1.0]),
            (1.0 / 3.0, [1.0, 1.0, 0.0]),
            (2.0 / 3.0, [1.0, 0.0, 1.0]),
            (1.0, [0.0, 1.0, 1.0]),
        ],
        "mandel" => &[
            (0.0, [0.0; 3]),
            (0.001, [0.0; 3]),
            (0.001, [0.0, 1.0, 1.0]),
            (0.012, [1.0, 1.0, 0.0]),
            (0.015, [1.0, 0.0, 1.0]),
            (0.1, [0.0, 1.0, 1.0]),
            (1.0, [0.0, 1.0, 1.0]),
        ],
        _ => &[(0.0, [0.0; 3]), (1.0, [1.0; 3])],
    };
    entries.iter().map(|&(value, [r, g, b])| ColorMapEntry { value, color: Color::rgb(r, g, b) }).collect()
}

/// POV-Ray reads a colour map in written order, not sorted: a value at or above the last
/// entry's gets the last colour; any other value blends the pair that ends at the first entry
/// at or above it (so an entry below an earlier one only starts the next pair, and values
/// outside 0–1 are fine). Measured by rendering `gradient x` maps with `ambient 1 diffuse 0`:
/// `[0 R][0.8 B][0.3 G]` is R→B up to 0.3, then G. This returns sorted entries that give the
/// same colours under the renderer's lookup (which assumes sorted entries); entries already in
/// order come back unchanged.
pub(in crate::pov::lower) fn sorted_map(entries: &[ColorMapEntry]) -> Vec<ColorMapEntry> {
    let Some((&first, &last)) = entries.first().zip(entries.last()) else { return Vec::new() };
    let mut out = vec![first];
    let mut top = first.value;
    for pair in entries.windows(2) {
        let (a, b) = (pair[0], pair[1]);
        if b.value <= top {
            continue;
        }
        // This pair is what values in (top, b] read.
        let start = ColorMapEntry { value: top, color: blend(a, b, top) };
        if out.last() != Some(&start) {
            out.push(start);
        }
        out.push(b);
        top = b.value;
    }
    if last.value < top {
        let below = ColorMapEntry { value: last.value, color: sorted_lookup(&out, last.value) };
        out.retain(|e| e.value < last.value);
        out.extend([below, last]);
    } else if out.last() != Some(&last) {
        // Ends at the top value with another colour: a hard step there.
        out.push(last);
    }
    out
}

/// The colour `a`→`b` gives at `v`.
fn blend(a: ColorMapEntry, b: ColorMapEntry, v: f64) -> Color {
    if v <= a.value {
        return a.color;
    }
    let t = (v - a.value) / (b.value - a.value);
    let mix = |x: f64, y: f64| x + (y - x) * t;
    Color {
        rgb: a.color.rgb + (b.color.rgb - a.color.rgb) * t,
        filter: mix(a.color.filter, b.color.filter),
        transmit: mix(a.color.transmit, b.color.transmit),
    }
}

/// The colour of sorted entries at `v`, as the renderer reads them.
fn sorted_lookup(entries: &[ColorMapEntry], v: f64) -> Color {
    match entries.iter().position(|e| v <= e.value) {
        Some(0) => entries[0].color,
        Some(i) => blend(entries[i - 1], entries[i], v),
        None => entries[entries.len() - 1].color,
    }
}

impl Lowerer<'_> {
    /// A colour map's entries in the sorted form the renderer reads (see `sorted_map`), or a
    /// copy of the declared map it names.
    pub(in crate::pov::lower) fn color_map(&mut self, m: &ColorMap) -> PResult<Vec<ColorMapEntry>> {
        let entries = match &m.body {
            ColorMapBody::Named(e) => {
                return match self.declared(e)? {
                    Some(Value::ColorMap(map)) => Ok(map.clone()),
                    Some(other) => Err(other.wrong_kind(e.span, "a declared color_map")),
                    None => Err(Diag::new(e.span, "expected the name of a declared color_map or `[` entries")),
                };
            }
            ColorMapBody::Entries(entries) => entries,
        };
        let mut out = Vec::with_capacity(entries.len());
        for entry in entries {
            out.push(ColorMapEntry { value: self.float(&entry.value)?, color: self.color(&entry.color)? });
        }
        Ok(sorted_map(&out))
    }
}
