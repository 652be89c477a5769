//! The binned-SAH build, on one thread or over rayon's pool, node for node the same.
//!
//! One node's work (`split_node`): its bounds and its centres' bounds, 16 bins per axis, the
//! cheapest plane, an in-place partition of its range of the primitives. The serial build
//! (`grow_serial`) pops nodes off a stack, right child first, and appends each split node's two
//! children to the node array. So a subtree's nodes form one contiguous block:
//! `[left, right][right's block][left's block]`. The parallel build (`subtree`) relies on that:
//! above `Grain::join_min` primitives both children are built at once (`rayon::join`), each into
//! blocks of its own with indices relative to the block, and the blocks are laid end to end
//! once the whole tree is known (`assemble`), which gives the serial array exactly.
//!
//! A primitive carries a weight: what its test costs, in node visits (1 for a sphere or a box,
//! more for a shape that walks its own tree or solves a quartic). The surface-area heuristic
//! weighs each side of a split by its primitives' weights instead of their number, so a tree
//! over costly shapes splits down to one per leaf where one over spheres keeps two to four.
//! With every weight 1 the tree is the unweighted one, bit for bit.
//!
//! Within a node nothing depends on the thread count either: bins and bounds are folds of `min`,
//! `max` and integer sums, which give the same bits in any grouping, and the parallel folds
//! cut the range into fixed-size chunks merged left to right. The partition, the one step whose
//! result depends on the order it runs in, always runs on one thread.

use glam::Vec3;
use rayon::prelude::*;

use super::{Bvh, BvhNode, MAX_DEPTH};
use crate::accel::aabb::Aabb;

/// SAH bins per axis. 16 bins build within a few percent of a full sweep's quality (Wald 2007)
/// at a fraction of the cost.
const BINS: usize = 16;
/// Leaves stop splitting at this size; larger leaves only when no split is cheaper.
const MAX_LEAF: usize = 4;
/// Relative cost of one node visit against one primitive test.
const TRAVERSAL_COST: f32 = 1.0;

/// When the build goes parallel. A task or a chunk costs a few microseconds to hand out, so
/// work is split only where it is worth hundreds of them.
#[derive(Clone, Copy, Debug)]
pub(super) struct Grain {
    /// Subtrees of at least this many primitives build their two children at once.
    pub join_min: usize,
    /// Nodes of at least this many primitives bin and bound in chunks of this size on the pool.
    pub chunk: usize,
}

impl Grain {
    /// On rayon's pool: a million primitives make about a hundred subtree tasks.
    pub const PARALLEL: Grain = Grain { join_min: 8192, chunk: 32768 };
    /// Everything on the calling thread: the reference the parallel build must match.
    pub const SERIAL: Grain = Grain { join_min: usize::MAX, chunk: usize::MAX };
}

/// A primitive as the build moves it: its box and its index. The build partitions these, not
/// indices into the caller's boxes, so that every pass over a node reads memory in order: at a
/// million primitives, chasing indices into a 24 MB array cost three times the build.
#[derive(Clone, Copy)]
struct Prim {
    bounds: Aabb,
    index: u32,
    weight: u32,
}

#[inline(always)]
fn center(p: &Prim) -> Vec3 {
    p.bounds.center()
}

/// `fold` over `order`, in chunks of `grain.chunk` on the pool when the range has several,
/// merged left to right; the same result as one fold, since every fold here is min, max and
/// integer sums.
fn fold_range<T: Send>(
    order: &[Prim],
    chunk: usize,
    init: impl Fn() -> T + Sync,
    fold: impl Fn(&mut T, &Prim) + Sync,
    merge: impl Fn(&mut T, &T),
) -> T {
    let run = |part: &[Prim]| {
        let mut acc = init();
        for p in part {
            fold(&mut acc, p);
        }
        acc
    };
    if order.len() < chunk.saturating_mul(2) {
        return run(order);
    }
    let parts: Vec<T> = order.par_chunks(chunk).map(run).collect();
    let mut acc = init();
    for part in &parts {
        merge(&mut acc, part);
    }
    acc
}

/// A node's box, the box of its primitives' centres, and their total weight.
fn node_bounds(order: &[Prim], chunk: usize) -> (Aabb, Aabb, u64) {
    fold_range(
        order,
        chunk,
        || (Aabb::EMPTY, Aabb::EMPTY, 0),
        |(b, c, w), prim| {
            b.grow(&prim.bounds);
            c.grow_point(center(prim));
            *w += prim.weight as u64;
        },
        |(b, c, w), (pb, pc, pw)| {
            b.grow(pb);
            c.grow(pc);
            *w += pw;
        },
    )
}

/// Per axis: the bins' boxes and the total weight of their primitives.
struct Bins {
    bounds: [[Aabb; BINS]; 3],
    weight: [[u64; BINS]; 3],
}

/// Best binned-SAH split: (axis, plane position, cost in primitive-test units).
fn best_split(order: &[Prim], centers: &Aabb, parent_area: f32, chunk: usize) -> Option<(usize, f32, f32)> {
    // Axes along which the centres spread; the others cannot be split.
    let live: [bool; 3] = std::array::from_fn(|a| centers.max[a] > centers.min[a]);
    let scale: [f32; 3] = std::array::from_fn(|a| BINS as f32 / (centers.max[a] - centers.min[a]));
    let bins = fold_range(
        order,
        chunk,
        || Bins { bounds: [[Aabb::EMPTY; BINS]; 3], weight: [[0; BINS]; 3] },
        |bins, prim| {
            let c = center(prim);
            for axis in (0..3).filter(|&a| live[a]) {
                let b = (((c[axis] - centers.min[axis]) * scale[axis]) as usize).min(BINS - 1);
                bins.bounds[axis][b].grow(&prim.bounds);
                bins.weight[axis][b] += prim.weight as u64;
            }
        },
        |bins, part| {
            for axis in 0..3 {
                for b in 0..BINS {
                    bins.bounds[axis][b].grow(&part.bounds[axis][b]);
                    bins.weight[axis][b] += part.weight[axis][b];
                }
            }
        },
    );
    let mut best: Option<(usize, f32, f32)> = None;
    for axis in (0..3).filter(|&a| live[a]) {
        let (bin_bounds, bin_weight) = (&bins.bounds[axis], &bins.weight[axis]);
        // Sweep from the left and from the right to get the area and weight on each side.
        // Every weight is at least 1, so a side of weight 0 is an empty side.
        let mut left_area = [0.0f32; BINS - 1];
        let mut left_weight = [0u64; BINS - 1];
        let mut acc = Aabb::EMPTY;
        let mut n = 0;
        for i in 0..BINS - 1 {
            acc.grow(&bin_bounds[i]);
            n += bin_weight[i];
            left_area[i] = acc.half_area();
            left_weight[i] = n;
        }
        let mut acc = Aabb::EMPTY;
        let mut n = 0;
        for i in (1..BINS).rev() {
            acc.grow(&bin_bounds[i]);
            n += bin_weight[i];
            let cost = TRAVERSAL_COST
                + (left_area[i - 1] * left_weight[i - 1] as f32 + acc.half_area() * n as f32)
                    / parent_area.max(f32::MIN_POSITIVE);
            if left_weight[i - 1] > 0 && n > 0 && best.is_none_or(|b| cost < b.2) {
                best = Some((axis, centers.min[axis] + i as f32 / scale[axis], cost));
            }
        }
    }
    best
}

/// One node over the primitives `order` at depth `depth`: its box, and how many of them go to
/// the left child (`order` partitioned so they come first), or None for a leaf.
fn split_node(order: &mut [Prim], depth: usize, chunk: usize) -> (Aabb, Option<usize>) {
    let count = order.len();
    let (node, centers, weight) = node_bounds(order, chunk);
    if count <= 1 || depth >= MAX_DEPTH {
        return (node, None);
    }
    let Some((axis, position, cost)) = best_split(order, &centers, node.half_area(), chunk) else {
        return (node, None);
    };
    if cost >= weight as f32 && count <= MAX_LEAF {
        return (node, None);
    }
    // Partition in place around the chosen plane.
    let mut left = 0;
    for i in 0..count {
        if center(&order[i])[axis] < position {
            order.swap(i, left);
            left += 1;
        }
    }
    if left == 0 || left == count {
        // All centres on one side (e.g. identical centres): split the range in half.
        left = count / 2;
    }
    (node, Some(left))
}

fn leaf(first: usize, count: usize) -> BvhNode {
    BvhNode { min: [0.0; 3], first: first as u32, max: [0.0; 3], count: count as u32 }
}

/// Builds the subtree whose root is `nodes[0]` (a leaf over `order`, which starts at
/// primitive `base` of the whole range) on this thread, appending its nodes; an interior node's `first` indexes
/// `nodes`. An explicit stack: a million primitives must not recurse a million deep on bad splits.
fn grow_serial(order: &mut [Prim], base: usize, depth: usize, nodes: &mut Vec<BvhNode>, chunk: usize) {
    let mut stack = vec![(0usize, depth)];
    while let Some((node_index, depth)) = stack.pop() {
        let (first, count) = (nodes[node_index].first as usize, nodes[node_index].count as usize);
        let (node_bounds, split) = split_node(&mut order[first - base..first - base + count], depth, chunk);
        nodes[node_index].min = node_bounds.min.to_array();
        nodes[node_index].max = node_bounds.max.to_array();
        let Some(left) = split else { continue };
        let child = nodes.len();
        nodes.push(leaf(first, left));
        nodes.push(leaf(first + left, count - left));
        nodes[node_index].first = child as u32;
        nodes[node_index].count = 0;
        stack.push((child, depth + 1));
        stack.push((child + 1, depth + 1));
    }
}

/// Part of a subtree's block of nodes: interior nodes' `first` counts from `nodes[skip]`.
struct Chunk {
    nodes: Vec<BvhNode>,
    skip: usize,
}

impl Chunk {
    fn len(&self) -> usize {
        self.nodes.len() - self.skip
    }
}

/// Builds the subtree over `order` (from primitive `base` of the whole range) at `depth`: its root node, whose
/// `first`, if interior, counts from the start of its block, and the block of all nodes below
/// it, in chunks laid end to end.
fn subtree(order: &mut [Prim], base: usize, depth: usize, grain: Grain) -> (BvhNode, Vec<Chunk>) {
    let count = order.len();
    if count < grain.join_min {
        let mut nodes = Vec::with_capacity(2 * count);
        nodes.push(leaf(base, count));
        grow_serial(order, base, depth, &mut nodes, grain.chunk);
        let mut root = nodes[0];
        if root.is_leaf() {
            return (root, Vec::new());
        }
        // The block starts after the root, at `nodes[1]`.
        root.first -= 1;
        return (root, vec![Chunk { nodes, skip: 1 }]);
    }
    let (node_bounds, split) = split_node(order, depth, grain.chunk);
    let mut root = leaf(base, count);
    root.min = node_bounds.min.to_array();
    root.max = node_bounds.max.to_array();
    let Some(left) = split else { return (root, Vec::new()) };
    let (lo, hi) = order.split_at_mut(left);
    let ((mut r, r_chunks), (mut l, l_chunks)) =
        rayon::join(|| subtree(hi, base + left, depth + 1, grain), || subtree(lo, base, depth + 1, grain));
    // The block: the children, then the right child's block, then the left one's (the order
    // the serial build's stack visits them in).
    let r_len: usize = r_chunks.iter().map(Chunk::len).sum();
    if !r.is_leaf() {
        r.first += 2;
    }
    if !l.is_leaf() {
        l.first += (2 + r_len) as u32;
    }
    root.first = 0;
    root.count = 0;
    let mut chunks = Vec::with_capacity(1 + r_chunks.len() + l_chunks.len());
    chunks.push(Chunk { nodes: vec![l, r], skip: 0 });
    chunks.extend(r_chunks);
    chunks.extend(l_chunks);
    (root, chunks)
}

/// The node array: `root`, then the chunks with their indices made absolute. Each chunk is
/// freed once copied, so the nodes are held about once, not twice.
fn assemble(mut root: BvhNode, chunks: Vec<Chunk>) -> Vec<BvhNode> {
    if let [only] = &chunks[..] {
        if only.skip == 1 {
            // One serial chunk already is the array, root and all.
            let mut nodes = chunks.into_iter().next().map(|c| c.nodes).unwrap_or_default();
            nodes.shrink_to_fit();
            return nodes;
        }
    }
    let total = 1 + chunks.iter().map(Chunk::len).sum::<usize>();
    let mut nodes = Vec::with_capacity(total);
    if !root.is_leaf() {
        root.first += 1;
    }
    nodes.push(root);
    for chunk in chunks {
        let at = nodes.len() as u32 - chunk.skip as u32;
        nodes.extend(chunk.nodes[chunk.skip..].iter().map(|n| {
            let mut n = *n;
            if !n.is_leaf() {
                n.first += at;
            }
            n
        }));
    }
    nodes
}

/// Builds over primitives with the given bounds and weights (each at least 1; all 1 where
/// `weights` is None); index `i` of `bounds` is primitive `i`.
pub(super) fn build(bounds: &[Aabb], weights: Option<&[u32]>, grain: Grain) -> Bvh {
    let weight = |i: usize| weights.map_or(1, |w| w[i].max(1));
    let mut prims: Vec<Prim> =
        bounds.iter().enumerate().map(|(i, b)| Prim { bounds: *b, index: i as u32, weight: weight(i) }).collect();
    if prims.is_empty() {
        return Bvh::default();
    }
    let (root, chunks) = subtree(&mut prims, 0, 1, grain);
    let nodes = assemble(root, chunks);
    Bvh { nodes, prim_order: prims.iter().map(|p| p.index).collect() }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Deterministic pseudo-random boxes: clustered, overlapping, some flat, some at ±0.
    fn random_boxes(n: usize, seed: u64) -> Vec<Aabb> {
        let mut state = seed;
        let mut next = move || {
            state = state.wrapping_add(0x9E37_79B9_7F4A_7C15);
            let mut x = state;
            x = (x ^ (x >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
            x = (x ^ (x >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
            ((x ^ (x >> 31)) >> 40) as f32 / (1u64 << 24) as f32
        };
        (0..n)
            .map(|i| {
                let cluster = Vec3::splat((i % 7) as f32 * 20.0);
                let c = cluster + Vec3::new(next(), next(), next()) * 50.0 - 25.0;
                let e = Vec3::new(next(), next(), next()) * if i % 5 == 0 { 0.0 } else { 2.0 };
                match i % 97 {
                    // Boxes touching zero from both sides and with both zeros.
                    0 => Aabb::new(Vec3::new(-0.0, 0.0, -1.0), Vec3::new(0.0, -0.0, 1.0)),
                    1 => Aabb::new(Vec3::ZERO, Vec3::ZERO),
                    _ => Aabb::new(c - e, c + e),
                }
            })
            .collect()
    }

    #[test]
    fn parallel_build_is_the_serial_build_bit_for_bit() {
        let pool = rayon::ThreadPoolBuilder::new().num_threads(4).build().unwrap();
        // Small grains so that a test-sized input goes through joins and chunked folds many levels deep.
        let fine = Grain { join_min: 64, chunk: 50 };
        for (n, seed) in [(0, 1), (1, 2), (2, 3), (63, 4), (1000, 5), (20_000, 6), (150_000, 7)] {
            let boxes = random_boxes(n, seed);
            let serial = build(&boxes, None, Grain::SERIAL);
            let weights: Vec<u32> = (0..n as u32).map(|i| i * 7 % 13 + 1).collect();
            let weighted = build(&boxes, Some(&weights), Grain::SERIAL);
            for grain in [fine, Grain::PARALLEL] {
                let parallel = pool.install(|| build(&boxes, None, grain));
                assert!(serial.same_as(&parallel), "{n} boxes, {grain:?}");
                let parallel = pool.install(|| build(&boxes, Some(&weights), grain));
                assert!(weighted.same_as(&parallel), "{n} weighted boxes, {grain:?}");
            }
        }
    }

    #[test]
    fn heavy_primitives_get_leaves_of_their_own() {
        // Four unit cubes in a row. Weighed 1 each, two share a leaf: a split costs a node
        // visit more than it saves. Weighed 16 each, every one is a leaf of its own.
        let boxes: Vec<Aabb> = (0..4)
            .map(|i| Aabb::new(Vec3::new(i as f32 * 1.1, 0.0, 0.0), Vec3::new(i as f32 * 1.1 + 1.0, 1.0, 1.0)))
            .collect();
        let largest_leaf = |b: &Bvh| b.nodes.iter().filter(|n| n.is_leaf()).map(|n| n.count).max().unwrap();
        let light = build(&boxes, None, Grain::SERIAL);
        assert_eq!(largest_leaf(&light), 2);
        assert_eq!(largest_leaf(&build(&boxes, Some(&[16; 4]), Grain::SERIAL)), 1);
        // Weights of 1 are the unweighted tree, bit for bit.
        assert!(build(&boxes, Some(&[1; 4]), Grain::SERIAL).same_as(&light));
    }

    #[test]
    fn the_comparison_sees_a_changed_tree() {
        // `same_as` must be able to fail: the same boxes in another order build another tree,
        // and one bit of one box changes a node.
        let boxes = random_boxes(5000, 9);
        let tree = build(&boxes, None, Grain::SERIAL);
        let mut reversed = boxes.clone();
        reversed.reverse();
        assert!(!tree.same_as(&build(&reversed, None, Grain::SERIAL)));
        let mut nudged = boxes.clone();
        nudged[1234].max.x = nudged[1234].max.x.next_up();
        let other = build(&nudged, None, Grain::SERIAL);
        assert!(tree.prim_order == other.prim_order && !tree.same_as(&other));
    }
}
