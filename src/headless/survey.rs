//! `strahl survey DIR`: renders every `.pov` under a folder at a small size, as a user would
//! (from the scene's own folder, no `-L`), and counts how many render; the others are grouped by
//! the first error each one stops at, named by the keyword it quotes.
//!
//! Every scene runs in its own `strahl render` process with a time limit, so a scene that hangs
//! or crashes is counted as such and cannot take the survey down with it.

use std::collections::BTreeMap;
use std::fmt::Write as _;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

use clap::Args;

use crate::headless::progress::Progress;
use crate::headless::{output, povray_ini, CliError};

#[derive(Args)]
pub struct SurveyCmd {
    /// Folder searched recursively for `.pov` files, e.g. /usr/share/povray-3.7/scenes.
    dir: PathBuf,
    /// Image width of each render.
    #[arg(short = 'W', long, default_value_t = 64, value_parser = clap::value_parser!(u32).range(1..=4096))]
    width: u32,
    /// Image height of each render.
    #[arg(short = 'H', long, default_value_t = 48, value_parser = clap::value_parser!(u32).range(1..=4096))]
    height: u32,
    /// Seconds a scene may take (parse and render) before it counts as timed out.
    #[arg(long, value_name = "S", default_value_t = 10.0, value_parser = parse_seconds)]
    timeout: f64,
    /// Also print every scene's outcome, one line each.
    #[arg(long)]
    list: bool,
    /// Groups of failures to print (the commonest first).
    #[arg(long, value_name = "N", default_value_t = 25)]
    top: usize,
    /// Print nothing while running (no progress bar).
    #[arg(short, long)]
    quiet: bool,
}

fn parse_seconds(s: &str) -> Result<f64, String> {
    match s.trim().parse::<f64>() {
        Ok(v) if v.is_finite() && v > 0.0 && v <= 3600.0 => Ok(v),
        _ => Err(format!("`{s}` is not a time limit: give seconds from 0 to 3600")),
    }
}

/// How one scene ended.
#[derive(Clone, Debug, PartialEq)]
pub enum Outcome {
    Rendered,
    /// Exited with an error: its first `error:` line, without the `error: file:line:col: ` prefix.
    Failed(String),
    TimedOut,
    /// Ended by a signal or an exit code strahl never uses (a panic is 101).
    Crashed(String),
}

/// Every `.pov` file under `dir`, sorted, so the survey's order and counts are reproducible.
pub fn scene_files(dir: &Path) -> Result<Vec<PathBuf>, CliError> {
    let mut found = Vec::new();
    let mut todo = vec![dir.to_path_buf()];
    while let Some(d) = todo.pop() {
        let entries =
            std::fs::read_dir(&d).map_err(|e| CliError::user(format!("{}: cannot read folder: {e}", d.display())))?;
        for entry in entries.flatten() {
            let path = entry.path();
            if path.is_dir() {
                todo.push(path);
            } else if path.extension().is_some_and(|e| e.eq_ignore_ascii_case("pov")) {
                found.push(path);
            }
        }
    }
    found.sort();
    Ok(found)
}

/// Copies the folder `from` (following links) into `to`, recursively.
fn copy_tree(from: &Path, to: &Path) -> Result<(), CliError> {
    std::fs::create_dir_all(to).map_err(|e| CliError::user(format!("{}: cannot create folder: {e}", to.display())))?;
    let entries =
        std::fs::read_dir(from).map_err(|e| CliError::user(format!("{}: cannot read folder: {e}", from.display())))?;
    for entry in entries.flatten() {
        let (src, dst) = (entry.path(), to.join(entry.file_name()));
        if src.is_dir() {
            copy_tree(&src, &dst)?;
        } else {
            std::fs::copy(&src, &dst).map_err(|e| {
                CliError::user(format!("{}: cannot copy into the survey's scratch: {e}", src.display()))
            })?;
        }
    }
    Ok(())
}

/// The message of the first `error:` line in a render's stderr, without its location.
pub fn first_error(stderr: &str) -> Option<String> {
    let line = stderr.lines().find_map(|l| l.strip_prefix("error: "))?;
    Some(strip_location(line).to_string())
}

/// `file.pov:12:5: message` → `message`; a message without a location is returned as it is.
fn strip_location(line: &str) -> &str {
    let mut parts = line.splitn(4, ':');
    match (parts.next(), parts.next(), parts.next(), parts.next()) {
        (Some(_), Some(l), Some(c), Some(rest))
            if l.trim().parse::<u32>().is_ok() && c.trim().parse::<u32>().is_ok() =>
        {
            rest.trim_start()
        }
        _ => line,
    }
}

/// The group a failure is counted in: the message with every quoted name but the first replaced
/// by `…`, and numbers and strings dropped, so `#macro is not supported` gathers all scenes that
/// stop at a macro whatever else the line says.
pub fn group_of(message: &str) -> String {
    // A declaration that needs a feature fails where it is used, naming the feature: the same
    // group as the feature written in place.
    let message = message.strip_prefix("this declaration cannot be used: ").unwrap_or(message);
    let mut out = String::new();
    let mut quoted = 0;
    let mut rest = message;
    while let Some(open) = rest.find('`') {
        out.push_str(&rest[..open]);
        let after = &rest[open + 1..];
        let Some(close) = after.find('`') else {
            rest = after;
            break;
        };
        quoted += 1;
        if quoted == 1 {
            let _ = write!(out, "`{}`", &after[..close]);
        } else {
            out.push('…');
        }
        rest = &after[close + 1..];
    }
    out.push_str(rest);
    // Lists of what is supported are the same for every scene of a group; drop them.
    let cut = out.find(" (").unwrap_or(out.len());
    let words: Vec<String> = out[..cut]
        .split_whitespace()
        .map(|w| {
            if w.starts_with('"') || w.trim_end_matches(',').parse::<f64>().is_ok() {
                "…".to_string()
            } else {
                w.to_string()
            }
        })
        .collect();
    words.join(" ")
}

/// What kind of scene feature a group of failures needs, for the survey's table: an object, a
/// pattern, a light, a camera, a global setting, atmosphere, ... or "language" for anything
/// that is not a scene feature strahl lacks.
pub fn needs(group: &str) -> &'static str {
    const ATMOSPHERE: &[&str] = &["`sky_sphere`", "`fog`", "`media`", "`rainbow`"];
    if group.starts_with("layered textures") {
        return "texture layers";
    }
    if !group.contains(" is not supported") && !group.contains(" are not supported") {
        return if group == "timed out" || group.starts_with("crashed") { "—" } else { "language / scene error" };
    }
    let context = group.split(" is not supported").nth(1).unwrap_or("");
    match context.trim() {
        c if c.starts_with("in pigment") || c.starts_with("in normal") || c.starts_with("in texture") => "pattern",
        c if c.starts_with("in light_source") => "light",
        c if c.starts_with("in camera") => "camera",
        c if c.starts_with("in global_settings") => "global setting",
        c if c.starts_with("in finish") || c.starts_with("in interior") => "finish / interior",
        _ if ATMOSPHERE.iter().any(|a| group.starts_with(a)) => "atmosphere",
        c if c.starts_with("in the scene") => "scene item",
        c if c.is_empty() || c.starts_with("inside") => "object / CSG",
        c if c.starts_with("in ") => "object modifier",
        _ => "other feature",
    }
}

/// Renders one scene in a child `strahl render` from the scene's folder.
fn survey_one(exe: &Path, scene: &Path, args: &SurveyCmd, scratch: &Path) -> Result<Outcome, CliError> {
    let folder = scene.parent().unwrap_or(Path::new("."));
    let image = scratch.join("survey.png");
    let log = scratch.join("stderr.txt");
    let err_file =
        std::fs::File::create(&log).map_err(|e| CliError::user(format!("{}: cannot write: {e}", log.display())))?;
    // The child runs in the scene's folder, so the scene is named relative to it: a survey of a
    // relative folder finds its scenes too.
    let name = scene.file_name().map(PathBuf::from).unwrap_or_else(|| scene.to_path_buf());
    let mut command = Command::new(exe);
    command.arg("render").arg(&name);
    // A sample rendered through its own .ini (`povray scene.ini`) is an animation: render its
    // first frame, as POV-Ray would, so that `frame_number` and `clock` have the values it sets.
    let ini = scene.with_extension("ini");
    if std::fs::read_to_string(&ini).is_ok_and(|text| povray_ini::animation(&text).is_some()) {
        command.arg("--ini").arg(ini.file_name().unwrap_or_default());
    }
    let mut child = command
        .args(["-W", &args.width.to_string(), "-H", &args.height.to_string(), "-q", "-o"])
        .arg(&image)
        .current_dir(folder)
        .stdin(Stdio::null())
        .stdout(Stdio::null())
        .stderr(err_file)
        .spawn()
        .map_err(|e| CliError::user(format!("cannot run {}: {e}", exe.display())))?;
    let deadline = Instant::now() + Duration::from_secs_f64(args.timeout);
    let status = loop {
        match child.try_wait() {
            Ok(Some(status)) => break status,
            Ok(None) if Instant::now() >= deadline => {
                let _ = child.kill();
                let _ = child.wait();
                return Ok(Outcome::TimedOut);
            }
            Ok(None) => std::thread::sleep(Duration::from_millis(5)),
            Err(e) => return Err(CliError::user(format!("waiting for {}: {e}", scene.display()))),
        }
    };
    let stderr = std::fs::read_to_string(&log).unwrap_or_default();
    Ok(match status.code() {
        Some(0) => Outcome::Rendered,
        Some(2) => Outcome::Failed(first_error(&stderr).unwrap_or_else(|| "exit code 2 without a message".into())),
        Some(code) => Outcome::Crashed(format!("exit code {code}")),
        None => Outcome::Crashed("killed by a signal".into()),
    })
}

/// The survey's summary: the count, a table by top-level folder, and the commonest failures.
pub fn summary(dir: &Path, results: &[(PathBuf, Outcome)], top: usize) -> String {
    let mut o = String::new();
    let rendered = results.iter().filter(|(_, r)| *r == Outcome::Rendered).count();
    let _ = writeln!(o, "survey of {}: {rendered} of {} scenes render", dir.display(), results.len());
    let mut folders: BTreeMap<String, (usize, usize)> = BTreeMap::new();
    let mut groups: BTreeMap<String, Vec<&Path>> = BTreeMap::new();
    for (scene, outcome) in results {
        let rel = scene.strip_prefix(dir).unwrap_or(scene);
        let folder = match rel.components().count() {
            0 | 1 => ".".to_string(),
            _ => rel.components().next().map(|c| c.as_os_str().to_string_lossy().into_owned()).unwrap_or_default(),
        };
        let entry = folders.entry(folder).or_default();
        entry.1 += 1;
        match outcome {
            Outcome::Rendered => entry.0 += 1,
            Outcome::Failed(m) => groups.entry(group_of(m)).or_default().push(rel),
            Outcome::TimedOut => groups.entry("timed out".into()).or_default().push(rel),
            Outcome::Crashed(how) => groups.entry(format!("crashed ({how})")).or_default().push(rel),
        }
    }
    let _ = writeln!(o, "\n| folder | render | scenes |\n|---|--:|--:|");
    for (folder, (ok, n)) in &folders {
        let _ = writeln!(o, "| {folder} | {ok} | {n} |");
    }
    let mut ranked: Vec<(&String, &Vec<&Path>)> = groups.iter().collect();
    ranked.sort_by(|a, b| b.1.len().cmp(&a.1.len()).then(a.0.cmp(b.0)));
    let mut kinds: BTreeMap<&str, usize> = BTreeMap::new();
    for (group, scenes) in &ranked {
        *kinds.entry(needs(group)).or_default() += scenes.len();
    }
    let mut kinds: Vec<_> = kinds.into_iter().collect();
    kinds.sort_by(|a, b| b.1.cmp(&a.1).then(a.0.cmp(b.0)));
    let _ = writeln!(o, "\nwhat the others need first:\n| scenes | needs |\n|--:|---|");
    for (kind, n) in kinds {
        let _ = writeln!(o, "| {n} | {kind} |");
    }
    let _ = writeln!(
        o,
        "\nfirst errors of the others, commonest first:\n| scenes | needs | first error | e.g. |\n|--:|---|---|---|"
    );
    for (group, scenes) in ranked.iter().take(top) {
        let _ = writeln!(o, "| {} | {} | {group} | {} |", scenes.len(), needs(group), scenes[0].display());
    }
    if ranked.len() > top {
        let rest: usize = ranked[top..].iter().map(|(_, s)| s.len()).sum();
        let _ = writeln!(o, "| {rest} | | ({} more groups) | |", ranked.len() - top);
    }
    o
}

pub fn run(args: &SurveyCmd) -> Result<(), CliError> {
    if !args.dir.is_dir() {
        return Err(CliError::user(format!("{}: not a folder", args.dir.display())));
    }
    let exe =
        std::env::current_exe().map_err(|e| CliError::user(format!("cannot find strahl's own executable: {e}")))?;
    if scene_files(&args.dir)?.is_empty() {
        return Err(CliError::user(format!("{}: no .pov files under it", args.dir.display())));
    }
    let scratch = std::env::temp_dir().join(format!("strahl-survey.{}", std::process::id()));
    std::fs::create_dir_all(&scratch)
        .map_err(|e| CliError::user(format!("{}: cannot create folder: {e}", scratch.display())))?;
    // Scenes run in a scratch copy of the folder: samples that write files beside themselves
    // (`#fopen`: the portfolio's HTML pages, mesh_camera's meshes) can, as in a user's own copy
    // of the samples, whoever owns DIR; and DIR itself is never written.
    let tree = scratch.join("tree");
    let copied = copy_tree(&args.dir, &tree).and_then(|()| scene_files(&tree));
    let scenes = match copied {
        Ok(scenes) => scenes,
        Err(e) => {
            let _ = std::fs::remove_dir_all(&scratch);
            return Err(e);
        }
    };
    let progress = Progress::new(scenes.len() as u64, "scenes", args.quiet);
    let mut results = Vec::with_capacity(scenes.len());
    for (i, scene) in scenes.iter().enumerate() {
        let outcome = survey_one(&exe, scene, args, &scratch);
        if args.list {
            if let Ok(o) = &outcome {
                println!("{}: {o:?}", args.dir.join(scene.strip_prefix(&tree).unwrap_or(scene)).display());
            }
        }
        results.push((scene.clone(), outcome));
        progress.update(i as u64 + 1);
    }
    progress.finish();
    let _ = std::fs::remove_dir_all(&scratch);
    let results = results
        .into_iter()
        .map(|(s, r)| r.map(|r| (args.dir.join(s.strip_prefix(&tree).unwrap_or(&s)), r)))
        .collect::<Result<Vec<_>, _>>()?;
    print!("{}", summary(&args.dir, &results, args.top));
    output::flush_stdout();
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn first_error_drops_the_location() {
        let stderr =
            "warning: x\nerror: /a/b.pov:3:5: `#macro` is not supported (supported directives: #if)\n  #macro\n";
        assert_eq!(first_error(stderr).as_deref(), Some("`#macro` is not supported (supported directives: #if)"));
        assert_eq!(first_error("error: --frames must be at least 1").as_deref(), Some("--frames must be at least 1"));
        assert_eq!(first_error("nothing here"), None);
    }

    #[test]
    fn failures_group_by_their_first_quoted_keyword() {
        let a = group_of("`cylinder` is not supported (supported: sphere, plane)");
        let b = group_of("`cylinder` is not supported (supported: sphere, plane, box)");
        assert_eq!(a, b);
        assert_eq!(a, "`cylinder` is not supported");
        assert_ne!(a, group_of("`cone` is not supported (supported: sphere)"));
        assert_eq!(
            group_of("expected `>` to close the vector, found number 20"),
            group_of("expected `>` to close the vector, found number 3")
        );
        assert_eq!(
            group_of("unknown keyword `locaton` in camera (expected one of: location)"),
            "unknown keyword `locaton` in camera"
        );
        assert_eq!(
            group_of("expected an expression, found string \"a.ttf\""),
            "expected an expression, found string …"
        );
    }

    #[test]
    fn groups_say_what_kind_of_feature_they_need() {
        assert_eq!(
            group_of("this declaration cannot be used: `cone` is not supported"),
            group_of("`cone` is not supported")
        );
        assert_eq!(needs(&group_of("`cone` is not supported (supported: sphere)")), "object / CSG");
        assert_eq!(needs(&group_of("`granite` is not supported in pigment (supported: checker)")), "pattern");
        assert_eq!(needs(&group_of("`area_light` is not supported in light_source")), "light");
        assert_eq!(needs(&group_of("`fog` is not supported in the scene")), "atmosphere");
        assert_eq!(needs(&group_of("`radiosity` is not supported in global_settings")), "global setting");
        assert_eq!(needs(&group_of("undefined identifier `Foo`")), "language / scene error");
        assert_eq!(
            needs(&group_of("layered textures (a `texture` over another one) are not supported yet")),
            "texture layers"
        );
    }

    #[test]
    fn summary_counts_by_folder_and_group() {
        let dir = Path::new("/s");
        let results = vec![
            (PathBuf::from("/s/objects/a.pov"), Outcome::Rendered),
            (PathBuf::from("/s/objects/b.pov"), Outcome::Failed("`cone` is not supported (x)".into())),
            (PathBuf::from("/s/textures/c.pov"), Outcome::Failed("`cone` is not supported (y)".into())),
            (PathBuf::from("/s/textures/d.pov"), Outcome::TimedOut),
        ];
        let s = summary(dir, &results, 10);
        assert!(s.starts_with("survey of /s: 1 of 4 scenes render"), "{s}");
        assert!(s.contains("| objects | 1 | 2 |") && s.contains("| textures | 0 | 2 |"), "{s}");
        assert!(s.contains("| 2 | object / CSG | `cone` is not supported | objects/b.pov |"), "{s}");
        assert!(s.contains("| 1 | — | timed out | textures/d.pov |"), "{s}");
        assert!(s.contains("what the others need first:\n| scenes | needs |\n|--:|---|\n| 2 | object / CSG |"), "{s}");
    }
}
