//! The isosurface's search along one ray, taken one function value at a time, so that the
//! eight lanes of a packet have their samples evaluated in one pass of the function's code
//! (`Program::eval_lanes`): each lane says where it wants the function next (`want`) and is
//! told the value (`tell`), until it has its answer (`answer`).
//!
//! The search is the one `Isosurface` documents: inside the container, an interval whose ends
//! have the same sign is skipped when `|g(a)| + |g(b)| > max_gradient · length`, any other is
//! halved, nearer half first, down to `accuracy`; a bracketed crossing is then narrowed by
//! secant steps (Illinois' variant) until the lane's rounding of the bracket's ends agrees. A
//! root that rounds onto the ray's `t_min` is searched past, up to `TRIES` times (as
//! `geometry::solve_lanes_f64` does for the shapes solved lane by lane). A shadow ray's search
//! (`any`) is not narrowed where its bracket's answer would certainly be taken.

use glam::DVec3;

use crate::desc::{Container, IsoParams};
use crate::ray::MISS;

/// Most function evaluations one ray's search may take: a surface that grazes the threshold
/// for a long way (a plane at the threshold) would otherwise be halved without end.
const MAX_EVALUATIONS: usize = 4096;

/// Entries of the search's stack of interval ends.
pub const STACK: usize = 80;

/// A search's stack of interval ends, held by its caller: a `Search` that held its own was
/// 1.4 kB, moved into the packet's array of eight as each was made (a `memmove` and a
/// `memset` a tenth of scenes/kernels/isosurface.pov's time).
pub type Stack = [Sample; STACK];

/// Most steps of the secant narrowing: its steps shrink a bracket to the lane's rounding in a
/// few (the bound only stops a function that is not continuous there).
const REFINE_STEPS: usize = 64;

/// Searches from a root that rounded onto `t_min`, the first included.
const TRIES: usize = 4;

/// A point of the ray and the function's value there.
pub type Sample = (f64, f64);

#[derive(Clone, Copy, Debug)]
enum State {
    /// The value at the search's near end.
    Near,
    /// The value at its far end.
    Far,
    /// The value at `m`, the middle of `left` and the stack's top.
    Middle { m: f64 },
    /// Narrowing the bracket `a`, `b` (`last`: which end the last cut replaced, −1 a, 1 b);
    /// the value at `x`. `coarse`: out of budget, the answer is taken whatever it is.
    Narrow { a: Sample, b: Sample, last: i8, k: usize, x: f64, coarse: bool },
    /// The lane's answer, as the lane holds it (`MISS` for none).
    Done(f64),
}

pub struct Search<'a> {
    container: &'a Container,
    params: &'a IsoParams,
    round: fn(f64) -> f64,
    pub o: DVec3,
    pub d: DVec3,
    /// The lane's own `t_min` and `t_max`.
    lo: f64,
    hi: f64,
    /// A shadow ray's search (`Shape::blocks`): a bracket that certainly holds the answer is
    /// answered by its far end, not narrowed.
    any: bool,
    /// Where this try starts (`lo`, or a root that rounded onto it), and tries so far.
    from: f64,
    tries: usize,
    len: f64,
    enter: f64,
    exit: f64,
    step: f64,
    skip: f64,
    lipschitz: f64,
    /// The far end's value, for the container's wall.
    far: f64,
    /// The near end of the interval on top of the stack; the stack holds the far ends of the
    /// intervals still to search, nearest on top (together they tile the span, in order).
    left: Sample,
    stack: &'a mut Stack,
    n: usize,
    evaluations: usize,
    state: State,
}

impl<'a> Search<'a> {
    /// The search of `o + t·d` in `(lo, hi)`, with `stack` for its intervals (what it held
    /// before does not matter).
    #[allow(clippy::too_many_arguments)]
    pub fn new(
        container: &'a Container,
        params: &'a IsoParams,
        round: fn(f64) -> f64,
        o: DVec3,
        d: DVec3,
        lo: f64,
        hi: f64,
        any: bool,
        stack: &'a mut Stack,
    ) -> Search<'a> {
        let mut s = Search {
            container,
            params,
            round,
            o,
            d,
            lo,
            hi,
            any,
            from: lo,
            tries: 0,
            len: d.length(),
            enter: 0.0,
            exit: 0.0,
            step: 0.0,
            skip: 0.0,
            lipschitz: 0.0,
            far: 0.0,
            left: (0.0, 0.0),
            stack,
            n: 0,
            evaluations: 0,
            state: State::Done(MISS as f64),
        };
        s.start(lo);
        s
    }

    /// Where the function is wanted next, `None` once answered.
    #[inline]
    pub fn want(&self) -> Option<f64> {
        match self.state {
            State::Near => Some(self.left.0),
            State::Far => Some(self.stack[0].0),
            State::Middle { m } => Some(m),
            State::Narrow { x, .. } => Some(x),
            State::Done(_) => None,
        }
    }

    /// The lane's answer (`MISS` for none), once `want` is `None`.
    pub fn answer(&self) -> f64 {
        match self.state {
            State::Done(t) => t,
            _ => MISS as f64,
        }
    }

    /// A try from `from` (the span inside the container, the near end wanted).
    fn start(&mut self, from: f64) {
        self.tries += 1;
        self.from = from;
        let Some((enter, exit)) = self.container.span(self.o, self.d) else { return self.finish(None) };
        if self.len == 0.0 || !self.len.is_finite() {
            return self.finish(None);
        }
        let (a, b) = (enter.max(from), exit.min(self.hi));
        // NaN ends compare false: no span.
        if a.partial_cmp(&b) != Some(std::cmp::Ordering::Less) {
            return self.finish(None);
        }
        (self.enter, self.exit) = (enter, exit);
        self.step = self.params.accuracy / self.len;
        // From the ray's own start, a crossing closer than this is the surface it left.
        self.skip = if enter > from { a } else { a + 0.5 * self.step };
        self.lipschitz = self.params.max_gradient * self.len;
        self.left = (a, 0.0);
        self.stack[0] = (b, 0.0);
        self.n = 1;
        self.evaluations = 2;
        self.state = State::Near;
    }

    /// The value at the point `want` named.
    pub fn tell(&mut self, g: f64) {
        match self.state {
            State::Near => {
                self.left.1 = g;
                // Entering the container where the function is inside: its wall is the surface.
                if !self.params.open && self.enter > self.from && g < 0.0 {
                    return self.finish(Some(self.enter));
                }
                self.state = State::Far;
            }
            State::Far => {
                self.stack[0].1 = g;
                self.far = g;
                self.search();
            }
            State::Middle { m } => {
                self.evaluations += 1;
                // The halves: (left, m) on top of (m, old top).
                self.stack[self.n] = (m, g);
                self.n += 1;
                self.search();
            }
            State::Narrow { mut a, mut b, mut last, k, x, coarse } => {
                if (g < 0.0) == (a.1 < 0.0) {
                    a = (x, g);
                    if last == -1 {
                        b.1 *= 0.5;
                    }
                    last = -1;
                } else {
                    b = (x, g);
                    if last == 1 {
                        a.1 *= 0.5;
                    }
                    last = 1;
                }
                self.narrow(a, b, last, k + 1, coarse);
            }
            State::Done(_) => {}
        }
    }

    /// Takes intervals off the stack until one needs a value (or a crossing is bracketed).
    fn search(&mut self) {
        while self.n > 0 {
            let (a, b) = (self.left, self.stack[self.n - 1]);
            if b.0 <= self.skip {
                self.n -= 1;
                self.left = b;
                continue;
            }
            let crosses = (a.1 < 0.0) != (b.1 < 0.0);
            if !crosses && a.1.abs() + b.1.abs() > self.lipschitz * (b.0 - a.0) {
                self.n -= 1;
                self.left = b;
                continue;
            }
            if b.0 - a.0 <= self.step {
                self.n -= 1;
                self.left = b;
                if crosses {
                    return self.narrow(a, b, 0, 0, false);
                }
                continue;
            }
            if self.evaluations >= MAX_EVALUATIONS || self.n + 1 > STACK {
                // Out of budget: answer a bracketed crossing coarsely, else give up.
                self.n -= 1;
                self.left = b;
                if crosses {
                    return self.narrow(a, b, 0, 0, true);
                }
                continue;
            }
            self.state = State::Middle { m: 0.5 * (a.0 + b.0) };
            return;
        }
        // Leaving the container from inside the function: its wall again.
        let p = &self.params;
        let wall = !p.open && self.exit < self.hi && self.far < 0.0 && self.exit > self.skip;
        self.finish(wall.then_some(self.exit))
    }

    /// The next secant cut of the bracket `a`, `b`, or its answer: narrowed until the lane's
    /// rounding of the ends agrees, then the secant through it.
    fn narrow(&mut self, a: Sample, b: Sample, last: i8, k: usize, coarse: bool) {
        // Every answer the narrowing could give lies in [a, b]: past `skip` and rounding above
        // `lo` when `a` does, so it would be taken.
        if self.any && k == 0 && (coarse || a.0 > self.skip) && (self.round)(a.0) > self.lo {
            return self.finish(Some(b.0));
        }
        let m = 0.5 * (a.0 + b.0);
        if k < REFINE_STEPS && (self.round)(a.0) != (self.round)(b.0) && m > a.0 && m < b.0 {
            let w = b.0 - a.0;
            // NaN fails the test: then halve.
            let mut x = (a.0 + w * (a.1 / (a.1 - b.1))).clamp(a.0 + w / 64.0, b.0 - w / 64.0);
            if !(x > a.0 && x < b.0) {
                x = m;
            }
            self.state = State::Narrow { a, b, last, k, x, coarse };
            return;
        }
        let t = if a.1 != b.1 { a.0 + (b.0 - a.0) * a.1 / (a.1 - b.1) } else { 0.5 * (a.0 + b.0) };
        let t = t.clamp(a.0, b.0);
        if coarse || t > self.skip {
            self.finish(Some(t));
        } else {
            self.search();
        }
    }

    /// A try's root, or none: the lane's answer, or another try past a root that rounds
    /// onto `lo`.
    fn finish(&mut self, t: Option<f64>) {
        self.state = State::Done(MISS as f64);
        let Some(t) = t else { return };
        let r = (self.round)(t);
        if r > self.lo {
            self.state = State::Done(r.min(self.hi));
        } else if self.tries < TRIES {
            self.start(t);
        }
    }
}
