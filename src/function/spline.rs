//! POV-Ray's `spline { }` value (3.3.1.11): points of 2 to 5 components keyed by a parameter,
//! evaluated as `S(t)` or `S(t, kind)` while the scene is read (`transforms.inc`'s
//! `Spline_Trans` flies objects along one), or per point inside a function body
//! (`function { S(x).y }`, language/splinefunction.pov), which is why it lives beside the
//! function compiler rather than in `pov`. The parser reads the block (`pov::parser::spline`);
//! this module owns the interpolation.
//!
//! The four kinds, measured against `povray` 3.7 `#debug` output on unevenly spaced keys
//! (0, 1, 2.5, 3, 5): every figure below matched to the 5 decimals printed.
//! - `linear_spline`: straight pieces between neighbouring points.
//! - `quadratic_spline`: the piece from `P[i]` to `P[i+1]` is the parabola (in the key) through
//!   `P[i-1], P[i], P[i+1]`; the first piece uses the first three points.
//! - `cubic_spline`: the Hermite cubic from `P[i]` to `P[i+1]` whose slope (per unit key) at a
//!   point is the mean of the slopes of the two straight pieces that meet there; the first and
//!   last points only shape those slopes, so it is defined from the second to the next-to-last.
//!   With evenly spaced keys this is the Catmull-Rom cubic that `geometry::spline` builds for
//!   prisms and lathes (tangent `(P[i+1] − P[i−1]) / 2`).
//! - `natural_spline`: the natural cubic spline (second derivative 0 at both ends) through all.
//!
//! Outside the defined range the spline holds its end value. Points with the same key: the
//! later replaces the earlier. Too few points for the kind (quadratic < 3, cubic < 4)
//! interpolate linearly, as `povray` does for two points.

/// How `S(t)` interpolates.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SplineKind {
    Linear,
    Quadratic,
    Cubic,
    Natural,
}

impl SplineKind {
    pub fn from_keyword(word: &str) -> Option<SplineKind> {
        Some(match word {
            "linear_spline" => SplineKind::Linear,
            "quadratic_spline" => SplineKind::Quadratic,
            "cubic_spline" => SplineKind::Cubic,
            "natural_spline" => SplineKind::Natural,
            _ => return None,
        })
    }
}

/// Most components a spline point may have (a colour with filter and transmit).
pub const MAX_COMPONENTS: usize = 5;

/// A spline's points sorted by key, each padded with zeros to five components.
#[derive(Clone, Debug, PartialEq)]
pub struct Spline {
    pub kind: SplineKind,
    keys: Vec<f64>,
    points: Vec<[f64; MAX_COMPONENTS]>,
    /// Components of the widest point written: the size of what `S(t)` returns.
    dims: usize,
}

/// `S(t).y` of a declared spline `S` in a function body: the spline (copied, since a compiled
/// function is shared by render threads and the parser holds splines in an `Rc`), the kind to
/// interpolate with and the component read.
#[derive(Clone, Debug, PartialEq)]
pub struct SplineRead {
    pub spline: Spline,
    pub kind: SplineKind,
    /// 0 for x, up to `MAX_COMPONENTS - 1`.
    pub index: usize,
}

impl SplineRead {
    pub fn value(&self, t: f64) -> f64 {
        self.spline.component(t, self.kind, self.index)
    }
}

impl Default for Spline {
    fn default() -> Self {
        Spline { kind: SplineKind::Linear, keys: Vec::new(), points: Vec::new(), dims: 2 }
    }
}

impl Spline {
    /// Adds the point `p` (2 to 5 components) at `key`, replacing one with the same key.
    pub fn insert(&mut self, key: f64, p: &[f64]) {
        let mut padded = [0.0; MAX_COMPONENTS];
        for (slot, v) in padded.iter_mut().zip(p) {
            *slot = *v;
        }
        self.dims = self.dims.max(p.len().min(MAX_COMPONENTS));
        match self.keys.binary_search_by(|k| k.total_cmp(&key)) {
            Ok(i) => self.points[i] = padded,
            Err(i) => {
                self.keys.insert(i, key);
                self.points.insert(i, padded);
            }
        }
    }

    pub fn len(&self) -> usize {
        self.keys.len()
    }

    pub fn is_empty(&self) -> bool {
        self.keys.is_empty()
    }

    /// `S(t)` interpolated as `kind`: `dims` components (a spline without points gives zeros).
    pub fn eval(&self, t: f64, kind: SplineKind) -> Vec<f64> {
        let mut out = self.eval_all(t, kind).to_vec();
        out.truncate(self.dims);
        out
    }

    /// Component `index` (0 for x) of `S(t)` interpolated as `kind`, without allocating: the
    /// per-point read of a function body. Past the widest point written it reads 0.
    pub fn component(&self, t: f64, kind: SplineKind, index: usize) -> f64 {
        self.eval_all(t, kind).get(index).copied().unwrap_or(0.0)
    }

    fn eval_all(&self, t: f64, kind: SplineKind) -> [f64; MAX_COMPONENTS] {
        let (k, p) = (&self.keys, &self.points);
        let n = k.len();
        if n == 0 {
            return [0.0; MAX_COMPONENTS];
        }
        let kind = match kind {
            SplineKind::Quadratic if n < 3 => SplineKind::Linear,
            SplineKind::Cubic if n < 4 => SplineKind::Linear,
            other => other,
        };
        // The points the curve runs between: a cubic's first and last only shape it.
        let (first, last) = if kind == SplineKind::Cubic { (1, n - 2) } else { (0, n - 1) };
        if n == 1 || t <= k[first] {
            return p[first];
        }
        if t >= k[last] {
            return p[last];
        }
        // The piece [k[i], k[i+1]] holding t.
        let i = k.partition_point(|&key| key <= t).clamp(first + 1, last) - 1;
        let h = k[i + 1] - k[i];
        let s = (t - k[i]) / h;
        match kind {
            SplineKind::Linear => lerp(&p[i], &p[i + 1], s),
            SplineKind::Quadratic => {
                let j = i.max(1) - 1;
                lagrange3([k[j], k[j + 1], k[j + 2]], [&p[j], &p[j + 1], &p[j + 2]], t)
            }
            SplineKind::Cubic => {
                // Slopes per unit key of the pieces around [i, i+1], meaned at each end.
                let slope = |a: usize| -> [f64; MAX_COMPONENTS] {
                    std::array::from_fn(|c| (p[a + 1][c] - p[a][c]) / (k[a + 1] - k[a]))
                };
                let (s0, s1, s2) = (slope(i - 1), slope(i), slope(i + 1));
                let (h00, h10, h01, h11) = hermite(s);
                std::array::from_fn(|c| {
                    let d0 = 0.5 * (s0[c] + s1[c]) * h;
                    let d1 = 0.5 * (s1[c] + s2[c]) * h;
                    h00 * p[i][c] + h10 * d0 + h01 * p[i + 1][c] + h11 * d1
                })
            }
            SplineKind::Natural => {
                let m = natural_second_derivatives(k, p);
                let (a, b) = (1.0 - s, s);
                std::array::from_fn(|c| {
                    a * p[i][c]
                        + b * p[i + 1][c]
                        + ((a * a * a - a) * m[i][c] + (b * b * b - b) * m[i + 1][c]) * h * h / 6.0
                })
            }
        }
    }
}

fn lerp(a: &[f64; MAX_COMPONENTS], b: &[f64; MAX_COMPONENTS], s: f64) -> [f64; MAX_COMPONENTS] {
    std::array::from_fn(|c| a[c] + (b[c] - a[c]) * s)
}

/// The parabola through three keyed points, at `t`.
fn lagrange3(k: [f64; 3], p: [&[f64; MAX_COMPONENTS]; 3], t: f64) -> [f64; MAX_COMPONENTS] {
    let l0 = (t - k[1]) * (t - k[2]) / ((k[0] - k[1]) * (k[0] - k[2]));
    let l1 = (t - k[0]) * (t - k[2]) / ((k[1] - k[0]) * (k[1] - k[2]));
    let l2 = (t - k[0]) * (t - k[1]) / ((k[2] - k[0]) * (k[2] - k[1]));
    std::array::from_fn(|c| l0 * p[0][c] + l1 * p[1][c] + l2 * p[2][c])
}

/// The cubic Hermite basis at `s ∈ [0, 1]`: weights of start, start slope, end, end slope.
fn hermite(s: f64) -> (f64, f64, f64, f64) {
    let (s2, s3) = (s * s, s * s * s);
    (2.0 * s3 - 3.0 * s2 + 1.0, s3 - 2.0 * s2 + s, -2.0 * s3 + 3.0 * s2, s3 - s2)
}

/// The natural spline's second derivatives at every point (0 at both ends): the tridiagonal
/// system solved by the Thomas algorithm.
fn natural_second_derivatives(k: &[f64], p: &[[f64; MAX_COMPONENTS]]) -> Vec<[f64; MAX_COMPONENTS]> {
    let n = k.len();
    let mut m = vec![[0.0; MAX_COMPONENTS]; n];
    if n < 3 {
        return m;
    }
    // Forward sweep over the interior rows: h[i-1] m[i-1] + 2 (h[i-1] + h[i]) m[i] + h[i] m[i+1] = r[i].
    let mut diag = vec![0.0; n];
    let mut rhs = vec![[0.0; MAX_COMPONENTS]; n];
    for i in 1..n - 1 {
        let (ha, hb) = (k[i] - k[i - 1], k[i + 1] - k[i]);
        let mut d = 2.0 * (ha + hb);
        let mut r: [f64; MAX_COMPONENTS] =
            std::array::from_fn(|c| 6.0 * ((p[i + 1][c] - p[i][c]) / hb - (p[i][c] - p[i - 1][c]) / ha));
        if i > 1 {
            let w = ha / diag[i - 1];
            d -= w * ha;
            for c in 0..MAX_COMPONENTS {
                r[c] -= w * rhs[i - 1][c];
            }
        }
        diag[i] = d;
        rhs[i] = r;
    }
    for i in (1..n - 1).rev() {
        let hb = k[i + 1] - k[i];
        for c in 0..MAX_COMPONENTS {
            m[i][c] = (rhs[i][c] - hb * m[i + 1][c]) / diag[i];
        }
    }
    m
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The keys and points of the measurement, and `povray` 3.7's `#debug` figures.
    fn measured() -> Spline {
        let mut s = Spline::default();
        for (t, p) in [(0.0, [0.0, 0.0]), (1.0, [1.0, 2.0]), (2.5, [3.0, 1.0]), (3.0, [4.0, 4.0]), (5.0, [6.0, 3.0])] {
            s.insert(t, &p);
        }
        s
    }

    fn close(got: Vec<f64>, want: [f64; 2]) {
        assert!((got[0] - want[0]).abs() < 1e-5 && (got[1] - want[1]).abs() < 1e-5, "{got:?} vs {want:?}");
    }

    #[test]
    fn kinds_match_povray() {
        let s = measured();
        // Key, then linear, quadratic, cubic and natural.
        type Case = (f64, [f64; 2], [f64; 2], [f64; 2], [f64; 2]);
        let cases: &[Case] = &[
            (-0.5, [0.0, 0.0], [0.0, 0.0], [1.0, 2.0], [0.0, 0.0]),
            (0.25, [0.25, 0.5], [0.225, 0.7], [1.0, 2.0], [0.24777, 0.78806]),
            (1.25, [1.33333, 1.83333], [1.29167, 2.16667], [1.29282, 1.94907], [1.25843, 1.69199]),
            (2.0, [2.33333, 1.33333], [2.26667, 1.86667], [2.24074, 0.74074], [2.16825, 0.22016]),
            (2.75, [3.5, 2.5], [3.47917, 2.29167], [3.51042, 2.49479], [3.50268, 2.42621]),
            (4.0, [5.0, 3.5], [5.4, 6.1], [4.0, 4.0], [5.32857, 5.79786]),
            (5.5, [6.0, 3.0], [6.0, 3.0], [4.0, 4.0], [6.0, 3.0]),
        ];
        for &(t, l, q, c, n) in cases {
            close(s.eval(t, SplineKind::Linear), l);
            close(s.eval(t, SplineKind::Quadratic), q);
            close(s.eval(t, SplineKind::Cubic), c);
            close(s.eval(t, SplineKind::Natural), n);
        }
    }

    #[test]
    fn widest_point_sizes_the_result_and_same_key_replaces() {
        let mut s = Spline::default();
        s.insert(0.0, &[1.0, 2.0]);
        s.insert(1.0, &[3.0, 4.0, 5.0, 6.0]);
        s.insert(2.0, &[1.0, 1.0]);
        // povray: <2, 3, 2.5, 3> (the short points padded with zeros).
        assert_eq!(s.eval(0.5, SplineKind::Linear), vec![2.0, 3.0, 2.5, 3.0]);
        s.insert(1.0, &[1.0, 2.0]);
        assert_eq!(s.len(), 3);
        assert_eq!(s.eval(0.5, SplineKind::Linear), vec![1.0, 2.0, 0.0, 0.0]);
    }

    #[test]
    fn too_few_points_interpolate_linearly() {
        let mut s = Spline::default();
        s.insert(0.0, &[0.0, 0.0, 0.0]);
        s.insert(1.0, &[1.0, 1.0, 1.0]);
        for kind in [SplineKind::Quadratic, SplineKind::Cubic, SplineKind::Natural] {
            assert_eq!(s.eval(0.5, kind), vec![0.5, 0.5, 0.5]);
        }
        assert_eq!(Spline::default().eval(0.5, SplineKind::Cubic), vec![0.0, 0.0]);
    }
}
