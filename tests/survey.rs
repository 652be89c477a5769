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

/// Include files strahl does not bundle come from POV-Ray's installed include folder, with no
/// `-L` (they were "not found" before). `finish.inc` and `consts.inc` parse today.
#[test]
#[ignore = "needs Debian's povray-includes (/usr/share/povray-3.7/include): .ci/run runs it with --ignored"]
fn povray_include_files_are_found_without_dash_l() {
    let includes = Path::new("/usr/share/povray-3.7/include");
    assert!(includes.join("finish.inc").is_file(), "install Debian's povray-includes to run this test");
    let dir = std::path::PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("survey-includes");
    std::fs::create_dir_all(&dir).unwrap_or_else(|e| panic!("{e}"));
    let scene = dir.join("s.pov");
    let text = "#include \"finish.inc\"\n#include \"consts.inc\"\ncamera { location <0, 0, -4> look_at 0 }\n\
                light_source { <5, 5, -5> rgb 1 }\nsphere { 0, 1 pigment { rgb 1 } finish { Shiny } }\n";
    std::fs::write(&scene, text).unwrap_or_else(|e| panic!("{e}"));
    let png = dir.join("s.png");
    let out = Command::new(env!("CARGO_BIN_EXE_strahl"))
        .args(["render", scene.to_str().unwrap_or_default(), "-W", "16", "-H", "12", "-q", "-o"])
        .arg(&png)
        .output()
        .unwrap_or_else(|e| panic!("cannot run strahl: {e}"));
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    assert!(png.is_file());
}
