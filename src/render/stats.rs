//! Render statistics, modelled on POV-Ray's block. Counters are plain integer sums per tile,
//! added in tile order, so they never depend on the thread count.

use std::ops::AddAssign;

use crate::scene::build::ShapeKind;

/// The kind of ray being traced, for statistics.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum RayKind {
    Primary,
    Reflected,
    Refracted,
}

#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct RenderStats {
    pub pixels: u64,
    pub samples: u64,
    pub primary_rays: u64,
    pub shadow_rays: u64,
    pub reflected_rays: u64,
    pub refracted_rays: u64,
    /// Deepest level reached, 1 = primary rays only (POV-Ray's "Max Level").
    pub max_depth: u32,
    /// Ray→shape tests and hits, indexed by `ShapeKind as usize`.
    pub tests: [u64; ShapeKind::COUNT],
    pub hits: [u64; ShapeKind::COUNT],
    /// Bounding-volume nodes or grid cells visited.
    pub nodes_visited: u64,
    /// Samples whose colour came out NaN or infinite (replaced by black); must stay zero.
    pub bad_samples: u64,
}

impl RenderStats {
    /// One ray of `kind` traced at recursion `level` (1 for primary rays).
    #[inline]
    pub fn count_ray(&mut self, kind: RayKind, level: u32) {
        match kind {
            RayKind::Primary => self.primary_rays += 1,
            RayKind::Reflected => self.reflected_rays += 1,
            RayKind::Refracted => self.refracted_rays += 1,
        }
        self.max_depth = self.max_depth.max(level);
    }

    #[inline]
    pub fn count_test(&mut self, kind: ShapeKind, hit: bool) {
        self.tests[kind as usize] += 1;
        self.hits[kind as usize] += hit as u64;
    }

    /// Tests and hits for a kind as the user sees it (ellipsoids count as spheres, smooth
    /// triangles as triangles).
    pub fn by_kind(&self, kind: ShapeKind) -> (u64, u64) {
        let i = kind as usize;
        let mut t = self.tests[i];
        let mut h = self.hits[i];
        let twin = match kind {
            ShapeKind::Sphere => Some(ShapeKind::Ellipsoid),
            ShapeKind::Triangle => Some(ShapeKind::SmoothTriangle),
            _ => None,
        };
        if let Some(twin) = twin {
            t += self.tests[twin as usize];
            h += self.hits[twin as usize];
        }
        (t, h)
    }

    pub fn total_rays(&self) -> u64 {
        self.primary_rays + self.shadow_rays + self.reflected_rays + self.refracted_rays
    }
}

impl AddAssign for RenderStats {
    fn add_assign(&mut self, o: RenderStats) {
        self.pixels += o.pixels;
        self.samples += o.samples;
        self.primary_rays += o.primary_rays;
        self.shadow_rays += o.shadow_rays;
        self.reflected_rays += o.reflected_rays;
        self.refracted_rays += o.refracted_rays;
        self.max_depth = self.max_depth.max(o.max_depth);
        for i in 0..self.tests.len() {
            self.tests[i] += o.tests[i];
            self.hits[i] += o.hits[i];
        }
        self.nodes_visited += o.nodes_visited;
        self.bad_samples += o.bad_samples;
    }
}
