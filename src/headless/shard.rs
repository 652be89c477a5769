//! `--shard I/N` and `--shard auto`: which part of a job this process renders, and how frames or
//! rows are dealt to the parts.
//!
//! A scheduler's job array runs the same command line N times and tells each task its index in
//! the environment, so `--shard auto` reads it there: Slurm, Kubernetes Indexed Jobs and AWS
//! Batch name it differently. Reading goes through a lookup function rather than the process
//! environment, so the tests can hand it any environment without touching the real one.
//!
//! Dealing is a pure function of (index, count, items, unit, chunk): every task of an array
//! computes the same split without talking to the others, and a merge can check coverage.

use std::fmt;
use std::ops::Range;
use std::str::FromStr;

/// Part `index` of `count` (0-based), `index < count`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Shard {
    pub index: u32,
    pub count: u32,
}

/// `--shard` as written: a fixed part, or `auto` (optionally `auto/N`, the count given, as a
/// Kubernetes Indexed Job needs: it tells a pod its index but not how many there are).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ShardSpec {
    Fixed(Shard),
    Auto { count: Option<u32> },
}

/// The most shards a job may have: far beyond any array a scheduler accepts (Slurm's default
/// MaxArraySize is 1001), small enough that part names and counts stay readable.
pub const MAX_SHARDS: u32 = 100_000;

impl Shard {
    pub fn new(index: u32, count: u32) -> Result<Shard, String> {
        if count == 0 || count > MAX_SHARDS {
            return Err(format!("shard count {count} is out of range: give 1 to {MAX_SHARDS}"));
        }
        if index >= count {
            return Err(format!(
                "shard {index}/{count} does not exist: shards are numbered from 0, so the index must be below {count}"
            ));
        }
        Ok(Shard { index, count })
    }

    /// The half-open ranges of `0..items` this shard renders, dealt in units of `unit` items:
    /// interleaved (unit k to shard k mod N), which evens out costs that vary along a path or
    /// down an image, or with `chunk` one contiguous run per shard (sizes differing by at most
    /// one unit). Adjacent ranges are joined; a shard may get nothing when there are fewer
    /// units than shards.
    pub fn deal(self, items: u32, unit: u32, chunk: bool) -> Vec<Range<u32>> {
        let unit = unit.max(1);
        let units = items.div_ceil(unit) as u64;
        let (i, n) = (self.index as u64, self.count as u64);
        let span = |a: u64, b: u64| (a as u32 * unit)..((b as u32).saturating_mul(unit)).min(items);
        if chunk {
            let (a, b) = (units * i / n, units * (i + 1) / n);
            return if a < b { vec![span(a, b)] } else { Vec::new() };
        }
        if n == 1 {
            return if units > 0 { vec![span(0, units)] } else { Vec::new() };
        }
        (i..units).step_by(n as usize).map(|k| span(k, k + 1)).collect()
    }

    /// The items of [`Shard::deal`], one by one.
    pub fn items(self, items: u32, unit: u32, chunk: bool) -> Vec<u32> {
        self.deal(items, unit, chunk).into_iter().flatten().collect()
    }
}

impl fmt::Display for Shard {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}/{}", self.index, self.count)
    }
}

const SYNTAX: &str = "write I/N (part I of N, counted from 0, e.g. 0/4), auto (the index and count from Slurm, \
                      AWS Batch or Kubernetes), or auto/N (the index from the scheduler, N given)";

impl FromStr for ShardSpec {
    type Err = String;

    fn from_str(s: &str) -> Result<ShardSpec, String> {
        let t = s.trim();
        let bad = || format!("`{s}` is not a shard: {SYNTAX}");
        let count = |c: &str| -> Result<u32, String> {
            let n: u32 = c.trim().parse().map_err(|_| bad())?;
            Shard::new(0, n).map(|_| n)
        };
        if t == "auto" {
            return Ok(ShardSpec::Auto { count: None });
        }
        let (a, b) = t.split_once('/').ok_or_else(bad)?;
        if a.trim() == "auto" {
            return Ok(ShardSpec::Auto { count: Some(count(b)?) });
        }
        let index: u32 = a.trim().parse().map_err(|_| bad())?;
        Ok(ShardSpec::Fixed(Shard::new(index, count(b)?)?))
    }
}

/// Where `--shard auto` found its shard, for the log line that says so.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Found {
    pub shard: Shard,
    /// e.g. "Slurm (SLURM_ARRAY_TASK_ID=5, SLURM_ARRAY_TASK_MIN=1 ...)".
    pub source: String,
}

impl ShardSpec {
    /// The shard this process renders, reading the scheduler's variables through `env` for
    /// `auto`. `None` from a fixed spec is impossible; errors say which variable is missing or
    /// wrong.
    pub fn resolve(self, env: &dyn Fn(&str) -> Option<String>) -> Result<Found, String> {
        match self {
            ShardSpec::Fixed(shard) => Ok(Found { shard, source: "--shard".into() }),
            ShardSpec::Auto { count } => from_env(env, count),
        }
    }
}

/// A variable as a whole number, or an error naming it.
fn number(env: &dyn Fn(&str) -> Option<String>, name: &str) -> Result<Option<u32>, String> {
    match env(name) {
        None => Ok(None),
        Some(v) if v.trim().is_empty() => Ok(None),
        Some(v) => v.trim().parse().map(Some).map_err(|_| format!("--shard auto: {name}={v} is not a whole number")),
    }
}

/// Reads the shard from a scheduler's environment: Slurm first, then AWS Batch, then
/// Kubernetes, the first whose index variable is set. `given` is the count of `auto/N`; where
/// the scheduler names a count too, the two must agree.
fn from_env(env: &dyn Fn(&str) -> Option<String>, given: Option<u32>) -> Result<Found, String> {
    let finish = |index: u32, count: Option<u32>, source: String| -> Result<Found, String> {
        let count = match (count, given) {
            (Some(c), Some(g)) if c != g => {
                return Err(format!("--shard auto/{g}: the scheduler says the array has {c} tasks ({source})"))
            }
            (Some(c), _) | (None, Some(c)) => c,
            (None, None) => {
                return Err(format!(
                    "--shard auto: {source} gives the index but not the number of tasks; write --shard auto/N"
                ))
            }
        };
        let shard = Shard::new(index, count).map_err(|e| format!("--shard auto: {e} ({source})"))?;
        Ok(Found { shard, source })
    };
    if let Some(id) = number(env, "SLURM_ARRAY_TASK_ID")? {
        // Arrays may start anywhere and step (`--array=1-7:2`): the index is the task's place in
        // the array, not its id. MIN/MAX/STEP are set for every array task; COUNT where the
        // Slurm is new enough.
        let min = number(env, "SLURM_ARRAY_TASK_MIN")?;
        let step = number(env, "SLURM_ARRAY_TASK_STEP")?.unwrap_or(1).max(1);
        let count = number(env, "SLURM_ARRAY_TASK_COUNT")?;
        let source = format!("Slurm: SLURM_ARRAY_TASK_ID={id}");
        let Some(min) = min else {
            return finish(id, count, source);
        };
        if id < min || (id - min) % step != 0 {
            return Err(format!(
                "--shard auto: SLURM_ARRAY_TASK_ID={id} is not in the array that starts at {min} in steps of {step}"
            ));
        }
        let count = match (count, number(env, "SLURM_ARRAY_TASK_MAX")?) {
            (Some(c), _) => Some(c),
            (None, Some(max)) if max >= min => Some((max - min) / step + 1),
            (None, _) => None,
        };
        return finish((id - min) / step, count, format!("{source}, MIN={min}, STEP={step}"));
    }
    if let Some(index) = number(env, "AWS_BATCH_JOB_ARRAY_INDEX")? {
        let count = number(env, "AWS_BATCH_JOB_ARRAY_SIZE")?;
        return finish(index, count, format!("AWS Batch: AWS_BATCH_JOB_ARRAY_INDEX={index}"));
    }
    if let Some(index) = number(env, "JOB_COMPLETION_INDEX")? {
        return finish(index, None, format!("Kubernetes: JOB_COMPLETION_INDEX={index}"));
    }
    Err("--shard auto: no scheduler's array index is set (SLURM_ARRAY_TASK_ID, AWS_BATCH_JOB_ARRAY_INDEX or \
         JOB_COMPLETION_INDEX); outside a job array give --shard I/N"
        .into())
}

/// The process environment, as [`ShardSpec::resolve`] reads it.
pub fn process_env(name: &str) -> Option<String> {
    std::env::var(name).ok()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn env(vars: &[(&str, &str)]) -> impl Fn(&str) -> Option<String> {
        let vars: Vec<(String, String)> = vars.iter().map(|(k, v)| (k.to_string(), v.to_string())).collect();
        move |name| vars.iter().find(|(k, _)| k == name).map(|(_, v)| v.clone())
    }

    fn auto(vars: &[(&str, &str)], count: Option<u32>) -> Result<Shard, String> {
        ShardSpec::Auto { count }.resolve(&env(vars)).map(|f| f.shard)
    }

    #[test]
    fn parses_fixed_and_auto() {
        assert_eq!("2/4".parse(), Ok(ShardSpec::Fixed(Shard { index: 2, count: 4 })));
        assert_eq!(" 0 / 1 ".parse(), Ok(ShardSpec::Fixed(Shard { index: 0, count: 1 })));
        assert_eq!("auto".parse(), Ok(ShardSpec::Auto { count: None }));
        assert_eq!("auto/8".parse(), Ok(ShardSpec::Auto { count: Some(8) }));
    }

    #[test]
    fn rejects_bad_shards_with_reasons() {
        for bad in ["", "3", "a/4", "1/b", "-1/4", "1/4/5", "auto/", "auto/x", "1..4"] {
            let e = bad.parse::<ShardSpec>().unwrap_err();
            assert!(e.contains("is not a shard"), "{bad}: {e}");
        }
        assert!("4/4".parse::<ShardSpec>().unwrap_err().contains("index must be below 4"));
        assert!("0/0".parse::<ShardSpec>().unwrap_err().contains("out of range"));
        assert!("auto/0".parse::<ShardSpec>().unwrap_err().contains("out of range"));
        assert!("0/100001".parse::<ShardSpec>().unwrap_err().contains("out of range"));
    }

    #[test]
    fn interleaved_deal_covers_everything_once() {
        for (items, unit, n) in [(24, 1, 4), (25, 1, 4), (3, 1, 5), (48, 8, 4), (50, 8, 3), (1, 8, 2), (0, 1, 3)] {
            let mut seen = vec![0u32; items as usize];
            for i in 0..n {
                for x in Shard::new(i, n).unwrap().items(items, unit, false) {
                    seen[x as usize] += 1;
                }
            }
            assert!(seen.iter().all(|&c| c == 1), "{items} items in units of {unit} over {n}: {seen:?}");
        }
        let s = Shard::new(1, 4).unwrap();
        assert_eq!(s.items(10, 1, false), vec![1, 5, 9]);
        assert_eq!(s.deal(40, 8, false), vec![8..16]);
        assert_eq!(Shard::new(0, 2).unwrap().deal(20, 8, false), vec![0..8, 16..20]);
        assert_eq!(Shard::new(0, 1).unwrap().deal(20, 8, false), vec![0..20]);
    }

    #[test]
    fn chunked_deal_is_contiguous_and_even() {
        let parts: Vec<Vec<Range<u32>>> = (0..4).map(|i| Shard::new(i, 4).unwrap().deal(10, 1, true)).collect();
        assert_eq!(parts, vec![vec![0..2], vec![2..5], vec![5..7], vec![7..10]]);
        // Rows in 8-row units: the last unit is cut at the image's edge.
        let parts: Vec<Vec<Range<u32>>> = (0..3).map(|i| Shard::new(i, 3).unwrap().deal(30, 8, true)).collect();
        assert_eq!(parts, vec![vec![0..8], vec![8..16], vec![16..30]]);
        assert_eq!(Shard::new(2, 3).unwrap().deal(2, 1, true), vec![1..2]);
        assert_eq!(Shard::new(0, 3).unwrap().deal(2, 1, true), Vec::<Range<u32>>::new());
    }

    #[test]
    fn slurm_with_count_or_min_max_step() {
        let v = [("SLURM_ARRAY_TASK_ID", "3"), ("SLURM_ARRAY_TASK_COUNT", "4"), ("SLURM_ARRAY_TASK_MIN", "0")];
        assert_eq!(auto(&v, None), Ok(Shard { index: 3, count: 4 }));
        // `--array=1-7:2` without COUNT: tasks 1, 3, 5, 7.
        let v = [
            ("SLURM_ARRAY_TASK_ID", "5"),
            ("SLURM_ARRAY_TASK_MIN", "1"),
            ("SLURM_ARRAY_TASK_MAX", "7"),
            ("SLURM_ARRAY_TASK_STEP", "2"),
        ];
        assert_eq!(auto(&v, None), Ok(Shard { index: 2, count: 4 }));
        assert_eq!(auto(&v, Some(4)), Ok(Shard { index: 2, count: 4 }));
        assert!(auto(&v, Some(5)).unwrap_err().contains("the scheduler says the array has 4 tasks"));
        let off = [("SLURM_ARRAY_TASK_ID", "4"), ("SLURM_ARRAY_TASK_MIN", "1"), ("SLURM_ARRAY_TASK_STEP", "2")];
        assert!(auto(&off, None).unwrap_err().contains("not in the array"));
        // `--array=0-3,9`: COUNT 5, so task 9 has no place among 5.
        let gap = [("SLURM_ARRAY_TASK_ID", "9"), ("SLURM_ARRAY_TASK_MIN", "0"), ("SLURM_ARRAY_TASK_COUNT", "5")];
        assert!(auto(&gap, None).unwrap_err().contains("index must be below 5"));
        let bad = [("SLURM_ARRAY_TASK_ID", "x")];
        assert!(auto(&bad, None).unwrap_err().contains("SLURM_ARRAY_TASK_ID=x is not a whole number"));
        let no_count = [("SLURM_ARRAY_TASK_ID", "1")];
        assert!(auto(&no_count, None).unwrap_err().contains("write --shard auto/N"));
        assert_eq!(auto(&no_count, Some(2)), Ok(Shard { index: 1, count: 2 }));
    }

    #[test]
    fn kubernetes_needs_the_count_and_aws_reads_the_size() {
        let k = [("JOB_COMPLETION_INDEX", "2")];
        assert!(auto(&k, None).unwrap_err().contains("Kubernetes"));
        assert_eq!(auto(&k, Some(3)), Ok(Shard { index: 2, count: 3 }));
        assert!(auto(&k, Some(2)).unwrap_err().contains("index must be below 2"));
        let a = [("AWS_BATCH_JOB_ARRAY_INDEX", "0"), ("AWS_BATCH_JOB_ARRAY_SIZE", "10")];
        assert_eq!(auto(&a, None), Ok(Shard { index: 0, count: 10 }));
        assert!(auto(&[("AWS_BATCH_JOB_ARRAY_INDEX", "0")], None).unwrap_err().contains("auto/N"));
        // Slurm's variables win over the others'.
        let both = [("JOB_COMPLETION_INDEX", "0"), ("SLURM_ARRAY_TASK_ID", "1"), ("SLURM_ARRAY_TASK_COUNT", "2")];
        assert_eq!(auto(&both, None), Ok(Shard { index: 1, count: 2 }));
    }

    #[test]
    fn auto_outside_an_array_says_what_to_do() {
        let e = auto(&[], None).unwrap_err();
        assert!(e.contains("no scheduler's array index is set") && e.contains("--shard I/N"), "{e}");
        assert_eq!(
            ShardSpec::Fixed(Shard { index: 1, count: 2 }).resolve(&env(&[])).map(|f| f.shard),
            Ok(Shard { index: 1, count: 2 })
        );
    }
}
