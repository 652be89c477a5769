//! What strahl reads of POV-Ray's `.ini` files: where POV-Ray itself finds include files (the
//! `Library_Path` entries of the user's and the system's `povray.ini`, else the folder Debian's
//! `povray-includes` installs), and the animation a scene's own `.ini` describes.
//!
//! The include folders come before strahl's bundled `scenes/include`, which is only the fallback
//! on a machine without POV-Ray's include files.

use std::path::{Path, PathBuf};

/// The folder Debian's `povray-includes` fills, used when no `povray.ini` names one.
pub const DEBIAN_INCLUDE_DIR: &str = "/usr/share/povray-3.7/include";

/// The `Library_Path` values of one `povray.ini`, in order: `Library_Path=DIR` or `+LDIR` lines,
/// quotes removed, `;` comments ignored, keys case-insensitive as POV-Ray reads them.
pub fn library_paths(ini: &str) -> Vec<PathBuf> {
    ini.lines()
        .filter_map(|line| {
            let line = line.split(';').next().unwrap_or("").trim();
            let value = match line.split_once('=') {
                Some((key, value)) if key.trim().eq_ignore_ascii_case("library_path") => value,
                _ => line.strip_prefix("+L").or_else(|| line.strip_prefix("+l"))?,
            };
            let value = value.trim().trim_matches('"').trim();
            (!value.is_empty()).then(|| PathBuf::from(value))
        })
        .collect()
}

/// POV-Ray's include folders on this machine that exist: the user's `povray.ini`, then the
/// system's, then Debian's folder if neither named one.
pub fn povray_include_dirs() -> Vec<PathBuf> {
    let mut inis = Vec::new();
    if let Some(home) = std::env::var_os("HOME") {
        inis.push(Path::new(&home).join(".povray/3.7/povray.ini"));
    }
    inis.push(PathBuf::from("/etc/povray/3.7/povray.ini"));
    let mut dirs: Vec<PathBuf> =
        inis.iter().filter_map(|f| std::fs::read_to_string(f).ok()).flat_map(|text| library_paths(&text)).collect();
    if dirs.is_empty() {
        dirs.push(PathBuf::from(DEBIAN_INCLUDE_DIR));
    }
    let mut seen = Vec::new();
    dirs.retain(|d| {
        d.is_dir() && !seen.contains(d) && {
            seen.push(d.clone());
            true
        }
    });
    dirs
}

/// The animation a scene's `.ini` describes (`Initial_Frame`, `Final_Frame`, `Initial_Clock`,
/// `Final_Clock`, or the switches `+KFI`, `+KFF`, `+KI`, `+KF`), POV-Ray's defaults filling the
/// keys it leaves out.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Animation {
    pub initial_frame: u32,
    pub final_frame: u32,
    pub initial_clock: f64,
    pub final_clock: f64,
}

/// The animation of an `.ini`'s text, or `None` when it names no frame range (a still image).
/// Values that are not numbers are left at their defaults, as a still image would be rendered.
pub fn animation(ini: &str) -> Option<Animation> {
    let mut a = Animation { initial_frame: 1, final_frame: 1, initial_clock: 0.0, final_clock: 1.0 };
    let mut animated = false;
    for line in ini.lines() {
        let line = line.split(';').next().unwrap_or("").trim();
        let (key, value) = match line.split_once('=') {
            Some((key, value)) => (key.trim().to_ascii_lowercase(), value.trim()),
            None => {
                let lower = line.to_ascii_lowercase();
                let Some(rest) = lower.strip_prefix('+') else { continue };
                let (key, n) = if let Some(v) = rest.strip_prefix("kfi") {
                    ("initial_frame", v)
                } else if let Some(v) = rest.strip_prefix("kff") {
                    ("final_frame", v)
                } else if let Some(v) = rest.strip_prefix("ki") {
                    ("initial_clock", v)
                } else if let Some(v) = rest.strip_prefix("kf") {
                    ("final_clock", v)
                } else {
                    continue;
                };
                (key.to_string(), &line[line.len() - n.len()..])
            }
        };
        match key.as_str() {
            "initial_frame" => {
                if let Ok(v) = value.parse::<u32>() {
                    a.initial_frame = v;
                    animated = true;
                }
            }
            "final_frame" => {
                if let Ok(v) = value.parse::<u32>() {
                    a.final_frame = v;
                    animated = true;
                }
            }
            "initial_clock" => a.initial_clock = value.parse().unwrap_or(a.initial_clock),
            "final_clock" => a.final_clock = value.parse().unwrap_or(a.final_clock),
            _ => {}
        }
    }
    (animated && a.initial_clock.is_finite() && a.final_clock.is_finite()).then_some(a)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn library_path_lines_of_povray_ini_are_read_in_order() {
        let ini = "Width = 800\n; Library_Path=/commented\nLibrary_Path=\"/usr/share/povray-3.7\"\n\
                   library_path = /opt/pov/include ; trailing comment\n+L/home/me/inc\nVerbose=On\n";
        assert_eq!(
            library_paths(ini),
            [PathBuf::from("/usr/share/povray-3.7"), PathBuf::from("/opt/pov/include"), PathBuf::from("/home/me/inc")]
        );
        assert!(library_paths("Library_Path=\"\"\n").is_empty());
    }

    #[test]
    fn an_ini_animation_is_read_with_povray_defaults() {
        let ini = "Antialias=On\nInitial_Frame=1\nFinal_Frame=33 ; frames\nInitial_Clock=0\nfinal_clock = 2\n";
        assert_eq!(
            animation(ini),
            Some(Animation { initial_frame: 1, final_frame: 33, initial_clock: 0.0, final_clock: 2.0 })
        );
        assert_eq!(
            animation("+KFI5\n+KFF9\n+KI0.5\n"),
            Some(Animation { initial_frame: 5, final_frame: 9, initial_clock: 0.5, final_clock: 1.0 })
        );
        assert_eq!(animation("Width=320\nInitial_Clock=0\n; Initial_Frame=3\n"), None);
        assert_eq!(animation("Initial_Frame=x\n"), None);
    }
}
