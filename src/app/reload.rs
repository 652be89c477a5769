//! Live reload: which files a scene reads, whether any of them changed on disk, and the last
//! scene that loaded. The render thread polls a [`Reloader`] and rebuilds its `Scene` from what
//! it returns; the window only shows the error message. No window types here.
//!
//! Changes are found by polling each file's modification time and length (no file-watching
//! crate: one `stat` per file every 250 ms costs microseconds). The parser does not report which
//! files it read, so `#include "name"` directives are found by a textual scan and resolved the
//! way the parser resolves them (the including file's folder, then the include path). A scan can
//! only over-watch (an include inside a comment or a false `#if` branch), never miss one.

use std::path::{Path, PathBuf};
use std::time::{Duration, Instant, SystemTime};

use crate::desc::SceneDesc;
use crate::headless::{include_path, load, CliError};
use crate::pov::{IncludePath, MAX_INCLUDE_DEPTH};

/// How often the files are checked for changes.
pub const POLL: Duration = Duration::from_millis(250);

/// What a file looked like at the last poll: modification time and length, or `None` when it
/// could not be read. Length catches two writes within the file system's mtime granularity.
pub type Stamp = Option<(SystemTime, u64)>;

pub fn stamp(path: &Path) -> Stamp {
    let meta = std::fs::metadata(path).ok()?;
    Some((meta.modified().ok()?, meta.len()))
}

/// The scene file and every file it `#include`s, directly or not; the scene file first, each file
/// once. An include that is not found is listed where it would be looked for first (next to the
/// file including it), so that creating it there counts as a change.
pub fn scene_files(scene: &Path, include: &IncludePath) -> Vec<PathBuf> {
    let mut files = vec![scene.to_path_buf()];
    let mut next = 0;
    // Breadth first; `MAX_INCLUDE_DEPTH` levels is as deep as the parser goes.
    for _ in 0..=MAX_INCLUDE_DEPTH {
        let end = files.len();
        if next == end {
            break;
        }
        for i in next..end {
            let Ok(text) = std::fs::read_to_string(&files[i]) else {
                continue;
            };
            let here = files[i].parent().map(Path::to_path_buf);
            for name in include_names(&text) {
                let found = here
                    .iter()
                    .chain(include.dirs.iter())
                    .map(|d| d.join(name))
                    .find(|p| p.is_file())
                    .or_else(|| here.as_ref().map(|d| d.join(name)));
                if let Some(p) = found {
                    if !files.contains(&p) {
                        files.push(p);
                    }
                }
            }
        }
        next = end;
    }
    files
}

/// The quoted names after each `#include` in `text`.
fn include_names(text: &str) -> Vec<&str> {
    let mut names = Vec::new();
    let mut rest = text;
    while let Some(i) = rest.find("#include") {
        rest = rest[i + "#include".len()..].trim_start();
        if let Some(quoted) = rest.strip_prefix('"') {
            if let Some(end) = quoted.find(['"', '\n']) {
                if quoted[end..].starts_with('"') && end > 0 {
                    names.push(&quoted[..end]);
                }
                rest = &quoted[end..];
            }
        }
    }
    names
}

/// Watches a scene's files and reloads it, keeping the last scene that loaded.
pub struct Reloader {
    scene: PathBuf,
    user_dirs: Vec<PathBuf>,
    include: IncludePath,
    /// Each watched file with its stamp at the last poll or load.
    watched: Vec<(PathBuf, Stamp)>,
    last_poll: Instant,
    good: SceneDesc,
    /// The message of the last failed load, until a load succeeds.
    error: Option<String>,
}

impl Reloader {
    /// Starts watching `scene` (loaded as `desc`) and the files it includes.
    pub fn new(scene: &Path, user_dirs: &[PathBuf], desc: SceneDesc) -> Reloader {
        let mut r = Reloader {
            scene: scene.to_path_buf(),
            user_dirs: user_dirs.to_vec(),
            include: include_path(user_dirs),
            watched: Vec::new(),
            last_poll: Instant::now(),
            good: desc,
            error: None,
        };
        r.rescan();
        r
    }

    /// Loads the scene file from disk and starts watching it.
    pub fn open(scene: &Path, user_dirs: &[PathBuf]) -> Result<Reloader, CliError> {
        let (desc, _) = load(scene, user_dirs)?;
        Ok(Reloader::new(scene, user_dirs, desc))
    }

    fn rescan(&mut self) {
        self.watched = scene_files(&self.scene, &self.include)
            .into_iter()
            .map(|p| {
                let s = stamp(&p);
                (p, s)
            })
            .collect();
    }

    /// The files being watched, the scene first.
    pub fn files(&self) -> impl Iterator<Item = &Path> {
        self.watched.iter().map(|(p, _)| p.as_path())
    }

    /// Whether a watched file changed since the last poll or load. Checks the disk at most once
    /// per [`POLL`]; in between it answers `false`.
    pub fn poll(&mut self) -> bool {
        if self.last_poll.elapsed() < POLL {
            return false;
        }
        self.changed_now()
    }

    /// Like [`Reloader::poll`], but checks the disk now. A file that changed is re-stamped, so
    /// each change is reported once.
    pub fn changed_now(&mut self) -> bool {
        self.last_poll = Instant::now();
        let mut changed = false;
        for (path, old) in &mut self.watched {
            let new = stamp(path);
            if new != *old {
                *old = new;
                changed = true;
            }
        }
        changed
    }

    /// Parses the scene again. On success it becomes the last good scene and the error clears;
    /// on failure the last good scene stays and the located error is kept for display.
    pub fn reload(&mut self) -> Result<&SceneDesc, &str> {
        // Stamp before reading, so that a write landing during the load is seen by the next poll.
        self.rescan();
        self.last_poll = Instant::now();
        match load(&self.scene, &self.user_dirs) {
            Ok((desc, _)) => {
                self.good = desc;
                self.error = None;
                Ok(&self.good)
            }
            Err(e) => Err(self.error.insert(e.message)),
        }
    }

    /// The scene that last loaded.
    pub fn last_good(&self) -> &SceneDesc {
        &self.good
    }

    /// The error of the last load, if it failed.
    pub fn error(&self) -> Option<&str> {
        self.error.as_deref()
    }
}

#[cfg(test)]
mod tests {
    use std::fs;
    use std::time::UNIX_EPOCH;

    use super::*;

    fn temp_dir(name: &str) -> PathBuf {
        let d = std::env::temp_dir().join(format!("strahl-reload-{name}-{}", std::process::id()));
        let _ = fs::remove_dir_all(&d);
        fs::create_dir_all(&d).unwrap();
        d
    }

    /// Writes `text` with a modification time `secs` after the epoch, so a change is visible
    /// regardless of the file system's timestamp granularity.
    fn write(path: &Path, text: &str, secs: u64) {
        fs::write(path, text).unwrap();
        let f = fs::File::options().write(true).open(path).unwrap();
        f.set_modified(UNIX_EPOCH + Duration::from_secs(secs)).unwrap();
    }

    const GOOD: &str = "camera { location <0, 1, -5> look_at <0, 1, 0> }\n\
                        light_source { <0, 5, -5> color rgb 1 }\n\
                        sphere { <0, 1, 0>, 1 pigment { color rgb <1, 0, 0> } }\n";
    const BROKEN: &str = "camera { location <0, 1, -5> look_at <0, 1, 0> }\n\
                          sphere { <0, 1, 0>, 1 pigment { colour_of_nothing } }\n";
    const TWO: &str = "camera { location <0, 1, -5> look_at <0, 1, 0> }\n\
                       sphere { <0, 1, 0>, 1 pigment { color rgb 1 } }\n\
                       sphere { <2, 1, 0>, 1 pigment { color rgb 1 } }\n";

    #[test]
    fn finds_includes_once_and_in_order() {
        let text = "#include \"a.inc\"\n#include   \"b.inc\" // x\n#include \"a.inc\"\n#include \"\n#include";
        assert_eq!(include_names(text), ["a.inc", "b.inc", "a.inc"]);

        let dir = temp_dir("scan");
        let lib = dir.join("lib");
        fs::create_dir_all(&lib).unwrap();
        write(&dir.join("s.pov"), "#include \"a.inc\"\n#include \"missing.inc\"\n", 1);
        write(&dir.join("a.inc"), "#include \"b.inc\"\n#include \"a.inc\"\n", 1);
        write(&lib.join("b.inc"), "#include \"s.pov\"\n", 1);
        let files = scene_files(&dir.join("s.pov"), &IncludePath { dirs: vec![lib.clone()] });
        // b.inc's "s.pov" is not next to it nor on the include path (the parser would fail too):
        // it is watched where it would be found first.
        let expect =
            [dir.join("s.pov"), dir.join("a.inc"), dir.join("missing.inc"), lib.join("b.inc"), lib.join("s.pov")];
        assert_eq!(files, expect);
        let _ = fs::remove_dir_all(&dir);
    }

    #[test]
    fn break_then_fix_keeps_the_last_good_scene() {
        let dir = temp_dir("cycle");
        let scene = dir.join("s.pov");
        write(&scene, GOOD, 100);
        let mut r = Reloader::open(&scene, &[]).unwrap();
        assert_eq!(r.last_good().objects.len(), 1);
        assert!(!r.changed_now(), "nothing changed yet");

        write(&scene, BROKEN, 200);
        assert!(r.changed_now());
        assert!(!r.changed_now(), "a change is reported once");
        let msg = r.reload().unwrap_err().to_string();
        assert!(msg.starts_with(&format!("{}:2:", scene.display())), "located: {msg}");
        assert_eq!(r.error(), Some(msg.as_str()));
        assert_eq!(r.last_good().objects.len(), 1, "the last good scene stays");

        write(&scene, TWO, 300);
        assert!(r.changed_now());
        assert_eq!(r.reload().unwrap().objects.len(), 2);
        assert_eq!(r.error(), None, "fixing the file clears the error");
        assert_eq!(r.last_good().objects.len(), 2);
        let _ = fs::remove_dir_all(&dir);
    }

    #[test]
    fn an_included_file_is_watched() {
        let dir = temp_dir("include");
        let scene = dir.join("s.pov");
        write(&dir.join("obj.inc"), "sphere { <0, 1, 0>, 1 pigment { color rgb 1 } }\n", 100);
        write(&scene, "camera { location <0, 1, -5> look_at <0, 1, 0> }\n#include \"obj.inc\"\n", 100);
        let mut r = Reloader::open(&scene, &[]).unwrap();
        assert!(r.files().any(|f| f.ends_with("obj.inc")));

        write(&dir.join("obj.inc"), "sphere { <0, 1, 0>, 1 pigment { color rgb 1 }\n", 200);
        assert!(r.changed_now());
        let msg = r.reload().unwrap_err().to_string();
        assert!(msg.contains("obj.inc"), "the error names the include: {msg}");

        // A file deleted and put back counts as two changes; the reload after each sees it.
        fs::remove_file(dir.join("obj.inc")).unwrap();
        assert!(r.changed_now());
        assert!(r.reload().is_err());
        write(&dir.join("obj.inc"), "box { 0, 1 pigment { color rgb 1 } }\n", 300);
        assert!(r.changed_now());
        assert_eq!(r.reload().unwrap().objects.len(), 1);
        let _ = fs::remove_dir_all(&dir);
    }

    #[test]
    fn poll_checks_the_disk_at_most_every_interval() {
        let dir = temp_dir("poll");
        let scene = dir.join("s.pov");
        write(&scene, GOOD, 100);
        let mut r = Reloader::open(&scene, &[]).unwrap();
        write(&scene, TWO, 200);
        // Just loaded: the next look at the disk is a full interval away.
        assert!(!r.poll());
        std::thread::sleep(POLL + Duration::from_millis(20));
        assert!(r.poll());
        let _ = fs::remove_dir_all(&dir);
    }
}
