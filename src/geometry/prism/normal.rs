//! The prism's normal: that of the face the hit named (`Prism::hit_faces`), or where none was
//! named (a CSG leaf's hit, a shadow ray's) the nearest of its caps and sides to a surface
//! point, found among the arcs of the point's cell (`cells::Cells`) where that settles it,
//! among all arcs otherwise.

use glam::{DVec2, DVec3};

use super::{arc, outward, Prism, FACE_H1, FACE_H2};

impl Prism {
    /// Takes arc `i`'s nearest point to `w` as `side` where it is nearer than `best`.
    fn nearer(&self, i: u32, w: DVec2, scale: f64, best: &mut f64, side: &mut Option<(u32, f64)>) {
        let p = &self.arcs[i as usize];
        let t = arc::nearest_t(p, w);
        let dist = (p.at(t) - w).length() * scale;
        if dist < *best {
            *best = dist;
            *side = Some((i, t));
        }
    }

    /// Takes the nearest to `w` of the arcs `arcs` as `side` where it is nearer than `best`.
    /// Only the arcs whose boxes and slabs lie nearer than `best` are solved, the nearest
    /// first: the point lies on that arc or a neighbour, and the distance to it then rules out
    /// the arcs that lie farther. Up to `N` are queued (the rest are solved as found): a cell
    /// lists a few, and a longer queue costs its clearing on every normal.
    fn nearest_of<const N: usize>(
        &self,
        arcs: impl Iterator<Item = u32>,
        w: DVec2,
        scale: f64,
        best: &mut f64,
        side: &mut Option<(u32, f64)>,
    ) {
        let mut near = [(0.0, 0u32); N];
        let mut count = 0;
        for i in arcs {
            let (p, slab) = (&self.arcs[i as usize], &self.slabs[i as usize]);
            let g = (p.lo - w).max(w - p.hi).max(DVec2::ZERO).length().max(slab.gap(w)) * scale;
            if g < *best {
                if count == near.len() {
                    self.nearer(i, w, scale, best, side);
                } else {
                    near[count] = (g, i);
                    count += 1;
                }
            }
        }
        let near = &mut near[..count];
        if let Some(first) = (0..count).min_by(|&i, &j| near[i].0.total_cmp(&near[j].0)) {
            near.swap(0, first);
        }
        for &(g, i) in near.iter() {
            if g < *best {
                self.nearer(i, w, scale, best, side);
            }
        }
    }

    /// The outward object-space normal at `q` on face `face` (`solve_face`): a cap's, or the
    /// side's over arc `face` at the arc's point nearest `q`'s section point; `normal_object`'s
    /// for a face not named (`u32::MAX`) or an arc with no tangent there.
    pub(super) fn normal_face(&self, face: u32, q: DVec3) -> DVec3 {
        match face {
            FACE_H1 => -DVec3::Y,
            FACE_H2 => DVec3::Y,
            i if (i as usize) < self.arcs.len() => {
                let w = self.section(q);
                let t = arc::nearest_t(&self.arcs[i as usize], w);
                self.side_normal(i, t, q).unwrap_or_else(|| self.normal_object(q))
            }
            _ => self.normal_object(q),
        }
    }

    /// The outward object-space normal at `q` on the surface: the nearest of the sides and caps.
    pub(super) fn normal_object(&self, q: DVec3) -> DVec3 {
        let w = self.section(q);
        // Cap distance in object units.
        let mut best = f64::INFINITY;
        let mut normal = DVec3::Y;
        if !self.open {
            for (h, n) in [(self.h1, -DVec3::Y), (self.h2, DVec3::Y)] {
                let dist = (q.y - h).abs();
                if dist < best {
                    best = dist;
                    normal = n;
                }
            }
        }
        // Side distances are measured in the section, scaled back to object units for a cone.
        let scale = if self.conic { q.y.abs() } else { 1.0 };
        let mut side: Option<(u32, f64)> = None;
        // The arcs of `w`'s cell first (none for most points on a cap): any other arc lies
        // farther from `w` than its margin in the cell, so when the nearest found lies nearer,
        // that is the nearest of all.
        let settled = match self.cells.near(w) {
            Some((list, margin)) => {
                self.nearest_of::<8>(list.iter().copied(), w, scale, &mut best, &mut side);
                best < margin * scale
            }
            None => false,
        };
        if !settled {
            self.nearest_of::<32>(0..self.arcs.len() as u32, w, scale, &mut best, &mut side);
        }
        match side {
            Some((i, t)) => self.side_normal(i, t, q).unwrap_or(normal),
            None => normal,
        }
    }

    /// The outward object-space normal of the side over arc `i` at its parameter `t`, for the
    /// surface point `q`; `None` where the arc has no tangent there.
    fn side_normal(&self, i: u32, t: f64, q: DVec3) -> Option<DVec3> {
        let p = &self.arcs[i as usize];
        let tan = p.tangent(t);
        let mut n2 = DVec2::new(tan.y, -tan.x).normalize_or_zero();
        if n2 == DVec2::ZERO {
            return None;
        }
        // Outward: the side of the curve where the section is not inside, settled for the
        // arc when the prism was built, or tested beside the point.
        let at = p.at(t);
        let flip = match self.outward[i as usize] {
            outward::KEEP => false,
            outward::FLIP => true,
            _ => {
                let eps = 1e-6 * (1.0 + at.abs().max_element());
                self.inside_2d(at + eps * n2)
            }
        };
        if flip {
            n2 = -n2;
        }
        Some(if self.conic { DVec3::new(n2.x, -n2.dot(at), n2.y) * q.y.signum() } else { DVec3::new(n2.x, 0.0, n2.y) })
    }
}
