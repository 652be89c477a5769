//! Where POV-Ray itself finds include files: the `Library_Path` entries of the user's and the
//! system's `povray.ini`, else the folder Debian's `povray-includes` installs.
//!
//! These come before strahl's bundled `scenes/include`, which is only the fallback on a machine
//! without POV-Ray's include files.

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
}
