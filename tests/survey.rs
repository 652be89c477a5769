//! The survey of POV-Ray 3.7's own sample scenes (Debian's `povray-examples`): the number that
//! render may only grow. The test is `#[ignore]`d because it needs that package; `.ci/run`
//! installs it and runs the test with `--ignored`, where a missing package is a failure, so a
//! survey that could not run is never counted as passed.

use std::path::Path;
use std::process::Command;

const SAMPLES: &str = "/usr/share/povray-3.7/scenes";

/// Scenes that rendered when this floor was last raised; raise it as features land.
const FLOOR: usize = 1;

#[test]
#[ignore = "needs Debian's povray-examples (/usr/share/povray-3.7/scenes): .ci/run runs it with --ignored"]
fn povray_sample_survey_never_drops_below_its_floor() {
    assert!(
        Path::new(SAMPLES).is_dir(),
        "{SAMPLES} is missing: install Debian's povray-examples (apt-get install povray-examples) to run the survey"
    );
    let out = Command::new(env!("CARGO_BIN_EXE_strahl"))
        .args(["survey", SAMPLES, "-q"])
        .output()
        .unwrap_or_else(|e| panic!("cannot run strahl: {e}"));
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(out.status.success(), "survey failed: {}", String::from_utf8_lossy(&out.stderr));
    eprintln!("{stdout}");
    let first = stdout.lines().next().unwrap_or_default();
    let counts: Vec<usize> = first
        .split(": ")
        .nth(1)
        .map(|rest| rest.split_whitespace().filter_map(|w| w.parse().ok()).collect())
        .unwrap_or_default();
    let [rendered, total] = counts[..] else { panic!("unexpected survey line: {first}") };
    assert!(total >= 300, "only {total} sample scenes found under {SAMPLES}");
    assert!(rendered >= FLOOR, "{rendered} of {total} sample scenes render, below the floor of {FLOOR}");
    assert!(!stdout.contains("crashed"), "a sample scene crashed strahl:\n{stdout}");
}
