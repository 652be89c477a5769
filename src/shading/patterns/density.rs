//! The `density_file` pattern: a df3 voxel grid (`crate::density_file`) looked up for one or
//! eight points.

use crate::density_file::DensityGrid;
use crate::lanes::{Lane, V3};

/// The grid for one or eight points, lane by lane.
#[inline(always)]
pub fn density<L: Lane>(p: V3<L>, grid: &DensityGrid, interpolate: u32) -> L {
    L::from_fn(|i| grid.value([p.x.get(i), p.y.get(i), p.z.get(i)], interpolate))
}
