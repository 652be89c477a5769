//! Writing files without leaving half-written ones behind: write to a sibling temporary file,
//! then rename over the target.

use std::fs;
use std::io::{BufWriter, Write};
use std::path::{Path, PathBuf};

use crate::headless::CliError;

/// A hidden name beside `path` to write to before renaming onto it.
pub fn temp_sibling(path: &Path) -> PathBuf {
    let name = path.file_name().map(|n| n.to_string_lossy().into_owned()).unwrap_or_default();
    path.with_file_name(format!(".{name}.{}.tmp", std::process::id()))
}

/// Checks, before any work, that a file can be written at `path`: it is not a folder and its
/// folder exists and accepts a new file (probed with an empty temporary file, removed at once).
/// `what` names the option in the error, e.g. `-o` or `--json`.
pub fn check_writable(what: &str, path: &Path) -> Result<(), CliError> {
    if path.is_dir() {
        return Err(CliError::user(format!("{what} {}: is a folder, not a file", path.display())));
    }
    let dir = match path.parent() {
        Some(d) if !d.as_os_str().is_empty() => d,
        _ => Path::new("."),
    };
    if !dir.is_dir() {
        return Err(CliError::user(format!("{what} {}: folder {} does not exist", path.display(), dir.display())));
    }
    let probe = temp_sibling(path);
    match fs::OpenOptions::new().write(true).create_new(true).open(&probe) {
        Ok(_) => {
            let _ = fs::remove_file(&probe);
            Ok(())
        }
        Err(e) => Err(CliError::user(format!("{what} {}: cannot write there: {e}", path.display()))),
    }
}

/// Checks, before any work and without creating anything, that folder `dir` can hold new files:
/// it is a folder that accepts a file, or it is missing and its nearest existing ancestor is.
pub fn check_folder_writable(what: &str, dir: &Path) -> Result<(), CliError> {
    let mut existing = dir;
    while !existing.as_os_str().is_empty() && fs::metadata(existing).is_err() {
        existing = existing.parent().unwrap_or(Path::new(""));
    }
    let existing = if existing.as_os_str().is_empty() { Path::new(".") } else { existing };
    if !existing.is_dir() {
        return Err(CliError::user(format!(
            "{what} {}: {} is not a folder, so no folder can be made there",
            dir.display(),
            existing.display()
        )));
    }
    let probe = existing.join(format!(".strahl-probe.{}.tmp", std::process::id()));
    match fs::OpenOptions::new().write(true).create_new(true).open(&probe) {
        Ok(_) => {
            let _ = fs::remove_file(&probe);
            Ok(())
        }
        Err(e) => Err(CliError::user(format!("{what} {}: cannot write in {}: {e}", dir.display(), existing.display()))),
    }
}

/// Creates `dir` and its missing parents.
pub fn create_dir(dir: &Path) -> Result<(), CliError> {
    fs::create_dir_all(dir).map_err(|e| CliError::user(format!("{}: cannot create folder: {e}", dir.display())))
}

/// `check_writable` for an image: strahl writes PNG only, so any other extension (`x.jpg`) is an
/// error rather than PNG bytes under a misleading name.
pub fn check_png_path(what: &str, path: &Path) -> Result<(), CliError> {
    let is_png = path.extension().is_some_and(|e| e.eq_ignore_ascii_case("png"));
    if !is_png && !path.is_dir() {
        return Err(CliError::user(format!(
            "{what} {}: strahl writes PNG images only; give a file name ending in .png",
            path.display()
        )));
    }
    check_writable(what, path)
}

/// Writes `bytes` to `path` atomically.
pub fn write_atomic(path: &Path, bytes: &[u8]) -> Result<(), CliError> {
    let tmp = temp_sibling(path);
    let result = fs::write(&tmp, bytes).and_then(|_| fs::rename(&tmp, path));
    if let Err(e) = result {
        let _ = fs::remove_file(&tmp);
        return Err(CliError::user(format!("{}: cannot write: {e}", path.display())));
    }
    Ok(())
}

/// Encodes 8-bit RGB as PNG bytes.
pub fn encode_png(width: u32, height: u32, rgb: &[u8]) -> Vec<u8> {
    let mut out = Vec::new();
    {
        let mut enc = png::Encoder::new(BufWriter::new(&mut out), width, height);
        enc.set_color(png::ColorType::Rgb);
        enc.set_depth(png::BitDepth::Eight);
        // Encoding into memory cannot fail for a well-formed buffer; a failure here is a bug.
        let mut w = enc.write_header().expect("PNG header into memory");
        w.write_image_data(rgb).expect("PNG data into memory");
        w.finish().expect("PNG end into memory");
    }
    out
}

/// Writes an 8-bit RGB PNG atomically.
pub fn write_png(path: &Path, width: u32, height: u32, rgb: &[u8]) -> Result<(), CliError> {
    write_atomic(path, &encode_png(width, height, rgb))
}

/// Reads an 8-bit RGB or RGBA PNG as (width, height, RGB bytes).
pub fn read_png(path: &Path) -> Result<(u32, u32, Vec<u8>), CliError> {
    let file = fs::File::open(path).map_err(|e| CliError::user(format!("{}: cannot open: {e}", path.display())))?;
    let mut dec = png::Decoder::new(std::io::BufReader::new(file));
    dec.set_transformations(png::Transformations::EXPAND | png::Transformations::STRIP_16);
    let mut reader = dec.read_info().map_err(|e| CliError::user(format!("{}: not a PNG: {e}", path.display())))?;
    let mut buf = vec![0; reader.output_buffer_size()];
    let info = reader.next_frame(&mut buf).map_err(|e| CliError::user(format!("{}: bad PNG: {e}", path.display())))?;
    let channels = info.color_type.samples();
    let px = (info.width * info.height) as usize;
    let mut rgb = Vec::with_capacity(px * 3);
    for i in 0..px {
        let s = &buf[i * channels..];
        match channels {
            1 | 2 => rgb.extend_from_slice(&[s[0], s[0], s[0]]),
            _ => rgb.extend_from_slice(&s[..3]),
        }
    }
    Ok((info.width, info.height, rgb))
}

/// Flushes and ignores a closed pipe (`strahl render ... | head`).
pub fn flush_stdout() {
    let _ = std::io::stdout().flush();
}
