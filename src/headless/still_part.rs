//! A part of a sharded still (`render --shard I/N`) and the merge of the parts into the whole
//! image (`strahl merge`, `render --merge`).
//!
//! A part is a PNG of its rows, stacked in order, with what it is written into the PNG itself
//! (an iTXt chunk holding JSON): the scene, the full image's size, the settings that change
//! pixels, the shard, the rows and the SHA-256 of its pixels. One self-describing file per task
//! means there is no second file to lose or mismatch, and the part can still be looked at.
//! The merge checks everything before writing (all parts of one render, every shard once,
//! every row once, pixels as recorded) and writes the whole with the same encoder as
//! `render`, so the merged file has the one-machine render's bytes.

use std::ops::Range;
use std::path::{Path, PathBuf};

use crate::headless::capture::{settings_json, sha256_hex};
use crate::headless::json::Json;
use crate::headless::shard::Shard;
use crate::headless::{output, CliError};
use crate::pov::Clock;
use crate::render::RenderSettings;
use crate::scene::build::AccelKind;

/// The iTXt keyword of a part's description.
const KEYWORD: &str = "strahl-part";
const FORMAT: &str = "strahl-still-part";
const VERSION: u64 = 1;

/// What identifies the render a part belongs to: parts merge only when this agrees.
#[derive(Clone, Debug, PartialEq)]
pub struct Render {
    /// The scene as the user wrote it.
    pub scene: String,
    pub width: u32,
    pub height: u32,
    /// `capture::settings_json`: what changes pixels besides the camera.
    pub settings: Json,
    /// The clock the scene was parsed at (`--ini`/`--frame`).
    pub clock: Json,
}

impl Render {
    pub fn new(scene: &Path, settings: &RenderSettings, res_scale: f32, accel: AccelKind, clock: &Clock) -> Render {
        Render {
            scene: scene.display().to_string(),
            width: settings.width,
            height: settings.height,
            settings: settings_json(settings, res_scale, accel),
            clock: clock_json(clock),
        }
    }

    /// The first field in which `self` and `o` differ, for an error that says which.
    fn difference(&self, o: &Render) -> Option<String> {
        if self.scene != o.scene {
            return Some(format!("scene {} vs {}", self.scene, o.scene));
        }
        if (self.width, self.height) != (o.width, o.height) {
            return Some(format!("size {}x{} vs {}x{}", self.width, self.height, o.width, o.height));
        }
        if self.settings != o.settings {
            return Some(format!("settings {} vs {}", compact(&self.settings), compact(&o.settings)));
        }
        if self.clock != o.clock {
            return Some(format!("clock {} vs {}", compact(&self.clock), compact(&o.clock)));
        }
        None
    }
}

fn compact(j: &Json) -> String {
    j.to_pretty().split_whitespace().collect::<Vec<_>>().join(" ")
}

fn clock_json(c: &Clock) -> Json {
    Json::object(vec![
        ("clock", Json::Number(c.clock)),
        ("clock_delta", Json::Number(c.clock_delta)),
        ("frame_number", Json::Number(c.frame_number as f64)),
        ("initial_clock", Json::Number(c.initial_clock)),
        ("final_clock", Json::Number(c.final_clock)),
        ("initial_frame", Json::Number(c.initial_frame as f64)),
        ("final_frame", Json::Number(c.final_frame as f64)),
        ("on", Json::Bool(c.on)),
    ])
}

/// One part: which render, which shard, which rows, and a checksum of its pixels.
#[derive(Clone, Debug, PartialEq)]
pub struct Part {
    pub render: Render,
    pub shard: Shard,
    /// Ascending, disjoint; the PNG holds them stacked in this order.
    pub rows: Vec<Range<u32>>,
    /// SHA-256 of the part's 8-bit RGB pixels (not of the PNG bytes).
    pub sha256: String,
}

/// Where `render -o OUT.png --shard I/N` writes its part: `OUT.shard-I-of-N.png` beside OUT.
pub fn part_path(output: &Path, shard: Shard) -> PathBuf {
    let stem = output.file_stem().map(|s| s.to_string_lossy().into_owned()).unwrap_or_default();
    output.with_file_name(format!("{stem}.shard-{}-of-{}.png", shard.index, shard.count))
}

impl Part {
    fn to_json(&self) -> Json {
        let rows =
            self.rows.iter().map(|r| Json::Array(vec![Json::Number(r.start as f64), Json::Number(r.end as f64)]));
        Json::object(vec![
            ("format", Json::str(FORMAT)),
            ("version", Json::Number(VERSION as f64)),
            ("scene", Json::str(&self.render.scene)),
            ("width", Json::Number(self.render.width as f64)),
            ("height", Json::Number(self.render.height as f64)),
            ("settings", self.render.settings.clone()),
            ("clock", self.render.clock.clone()),
            ("shard", Json::Number(self.shard.index as f64)),
            ("shards", Json::Number(self.shard.count as f64)),
            ("rows", Json::Array(rows.collect())),
            ("sha256", Json::str(&self.sha256)),
        ])
    }

    fn from_json(v: &Json) -> Result<Part, String> {
        if v.get("format").and_then(Json::as_str) != Some(FORMAT)
            || v.get("version").and_then(Json::as_u64) != Some(VERSION)
        {
            return Err(format!("not a {FORMAT} version {VERSION}"));
        }
        let field = |k: &str| v.get(k).cloned().ok_or_else(|| format!("missing `{k}`"));
        let int = |j: &Json, k: &str| {
            j.as_u64()
                .filter(|&n| n <= u32::MAX as u64)
                .map(|n| n as u32)
                .ok_or_else(|| format!("`{k}` is not a count"))
        };
        let string = |k: &str| field(k)?.as_str().map(str::to_string).ok_or_else(|| format!("`{k}` is not a string"));
        let mut rows = Vec::new();
        for r in field("rows")?.as_array().ok_or("`rows` is not an array")? {
            match r.as_array() {
                Some([a, b]) => rows.push(int(a, "rows")?..int(b, "rows")?),
                _ => return Err("`rows` holds something other than [start, end] pairs".into()),
            }
        }
        let shard = Shard::new(int(&field("shard")?, "shard")?, int(&field("shards")?, "shards")?)?;
        Ok(Part {
            render: Render {
                scene: string("scene")?,
                width: int(&field("width")?, "width")?,
                height: int(&field("height")?, "height")?,
                settings: field("settings")?,
                clock: field("clock")?,
            },
            shard,
            rows,
            sha256: string("sha256")?,
        })
    }

    /// Rows in the part.
    pub fn row_count(&self) -> u32 {
        self.rows.iter().map(|r| r.end.saturating_sub(r.start)).sum()
    }
}

/// Writes a part's PNG (its rows' 8-bit RGB, `width` wide) with its description, atomically.
pub fn write(path: &Path, part: &Part, rgb: &[u8]) -> Result<(), CliError> {
    let mut bytes = Vec::new();
    let result = (|| -> Result<(), png::EncodingError> {
        let mut enc = png::Encoder::new(&mut bytes, part.render.width, part.row_count());
        enc.set_color(png::ColorType::Rgb);
        enc.set_depth(png::BitDepth::Eight);
        enc.add_itxt_chunk(KEYWORD.to_string(), part.to_json().to_pretty())?;
        let mut w = enc.write_header()?;
        w.write_image_data(rgb)?;
        w.finish()
    })();
    result.map_err(|e| CliError::user(format!("{}: cannot encode the part: {e}", path.display())))?;
    output::write_atomic(path, &bytes)
}

/// Reads a part: its description and its rows' pixels, checked against each other.
pub fn read(path: &Path) -> Result<(Part, Vec<u8>), CliError> {
    let shown = path.display();
    let file = std::fs::File::open(path).map_err(|e| CliError::user(format!("{shown}: cannot open: {e}")))?;
    let mut reader = png::Decoder::new(std::io::BufReader::new(file))
        .read_info()
        .map_err(|e| CliError::user(format!("{shown}: not a PNG: {e}")))?;
    let text = reader
        .info()
        .utf8_text
        .iter()
        .find(|t| t.keyword == KEYWORD)
        .map(|t| t.get_text())
        .transpose()
        .map_err(|e| CliError::user(format!("{shown}: unreadable part description: {e}")))?
        .ok_or_else(|| {
            CliError::user(format!("{shown}: not a part of a sharded render (no `{KEYWORD}` text in the PNG)"))
        })?;
    let part = Json::parse(&text)
        .and_then(|j| Part::from_json(&j))
        .map_err(|e| CliError::user(format!("{shown}: bad part description: {e}")))?;
    let info = reader.info();
    if (info.color_type, info.bit_depth) != (png::ColorType::Rgb, png::BitDepth::Eight) {
        return Err(CliError::user(format!("{shown}: not 8-bit RGB, so not as strahl wrote it")));
    }
    if (info.width, info.height) != (part.render.width, part.row_count()) {
        return Err(CliError::user(format!(
            "{shown}: the image is {}x{} but its description says {}x{}",
            info.width,
            info.height,
            part.render.width,
            part.row_count()
        )));
    }
    let mut rgb = vec![0; reader.output_buffer_size()];
    reader.next_frame(&mut rgb).map_err(|e| CliError::user(format!("{shown}: bad PNG: {e}")))?;
    if sha256_hex(&rgb) != part.sha256 {
        return Err(CliError::user(format!("{shown}: pixels do not match the part's sha256 (damaged or edited)")));
    }
    Ok((part, rgb))
}

/// Joins parts into the whole image's 8-bit RGB. The parts must be of one render (and of
/// `expect`, where given: `render --merge` checks them against its own command line), their
/// shards `0..N` of one N each once, and their rows every row of the image once.
pub fn join(parts: &[(PathBuf, Part, Vec<u8>)], expect: Option<&Render>) -> Result<(Render, Vec<u8>), CliError> {
    let (first_path, first, _) = parts.first().ok_or_else(|| CliError::user("no parts to merge"))?;
    let render = expect.unwrap_or(&first.render);
    let count = first.shard.count;
    let mut by_index: Vec<Option<&Path>> = vec![None; count as usize];
    for (path, part, _) in parts {
        if let Some(d) = render.difference(&part.render) {
            let against =
                if expect.is_some() { "this command line".to_string() } else { first_path.display().to_string() };
            return Err(CliError::user(format!(
                "cannot merge: {} is of another render than {against} ({d})",
                path.display()
            )));
        }
        if part.shard.count != count {
            return Err(CliError::user(format!(
                "cannot merge: {} is a part of {} shards, {} of {count}",
                path.display(),
                part.shard.count,
                first_path.display()
            )));
        }
        if let Some(other) = by_index[part.shard.index as usize].replace(path) {
            return Err(CliError::user(format!(
                "cannot merge: {} and {} are both shard {}",
                other.display(),
                path.display(),
                part.shard
            )));
        }
    }
    let missing: Vec<String> =
        by_index.iter().enumerate().filter(|(_, p)| p.is_none()).map(|(i, _)| i.to_string()).collect();
    if !missing.is_empty() {
        let shown = missing.iter().take(10).cloned().collect::<Vec<_>>().join(", ");
        let more = if missing.len() > 10 { format!(" and {} more", missing.len() - 10) } else { String::new() };
        return Err(CliError::user(format!("cannot merge: shard {shown}{more} of {count} is missing")));
    }
    let (w, h) = (render.width as usize, render.height as usize);
    let mut rgb = vec![0u8; w * h * 3];
    let mut owner: Vec<Option<&Path>> = vec![None; h];
    for (path, part, px) in parts {
        let mut src = px.chunks_exact(w * 3);
        for y in part.rows.iter().flat_map(|r| r.clone()) {
            let y = y as usize;
            if y >= h {
                return Err(CliError::user(format!("cannot merge: {} has row {y} of a {h}-row image", path.display())));
            }
            if let Some(other) = owner[y].replace(path) {
                return Err(CliError::user(format!(
                    "cannot merge: row {y} is in both {} and {}",
                    other.display(),
                    path.display()
                )));
            }
            let row =
                src.next().ok_or_else(|| CliError::user(format!("{}: fewer rows than listed", path.display())))?;
            rgb[y * w * 3..][..w * 3].copy_from_slice(row);
        }
    }
    if let Some(y) = owner.iter().position(Option::is_none) {
        return Err(CliError::user(format!("cannot merge: no part has row {y} of {h}")));
    }
    Ok((render.clone(), rgb))
}

/// `strahl merge PART... -o OUT.png` (and `render --merge`): reads and checks every part, then
/// writes the whole image; nothing is written when any check fails.
pub fn merge(paths: &[PathBuf], out: &Path, expect: Option<&Render>, quiet: bool) -> Result<(), CliError> {
    output::check_png_path("-o", out)?;
    let mut parts = Vec::new();
    for p in paths {
        let (part, rgb) = read(p)?;
        parts.push((p.clone(), part, rgb));
    }
    let (render, rgb) = join(&parts, expect)?;
    output::write_png(out, render.width, render.height, &rgb)?;
    if !quiet {
        println!("merged {} parts into {} ({}x{})", parts.len(), out.display(), render.width, render.height);
        output::flush_stdout();
    }
    Ok(())
}

/// The parts `render -o OUT.png --shard I/N` wrote beside OUT: `OUT.shard-I-of-N.png` for one N.
/// Parts of two different N there (a stale run) are refused rather than guessed between.
pub fn find_parts(out: &Path) -> Result<Vec<PathBuf>, CliError> {
    let stem = out.file_stem().map(|s| s.to_string_lossy().into_owned()).unwrap_or_default();
    let dir = match out.parent() {
        Some(d) if !d.as_os_str().is_empty() => d.to_path_buf(),
        _ => PathBuf::from("."),
    };
    let listing =
        std::fs::read_dir(&dir).map_err(|e| CliError::user(format!("{}: cannot read folder: {e}", dir.display())))?;
    let prefix = format!("{stem}.shard-");
    let mut found: Vec<(u32, u32, PathBuf)> = Vec::new();
    for entry in listing.filter_map(|e| e.ok()) {
        let name = entry.file_name().to_string_lossy().into_owned();
        let Some(rest) = name.strip_prefix(&prefix).and_then(|r| r.strip_suffix(".png")) else {
            continue;
        };
        let Some((i, n)) = rest.split_once("-of-") else {
            continue;
        };
        if let (Ok(i), Ok(n)) = (i.parse::<u32>(), n.parse::<u32>()) {
            found.push((n, i, entry.path()));
        }
    }
    found.sort();
    let counts: std::collections::BTreeSet<u32> = found.iter().map(|(n, _, _)| *n).collect();
    match counts.len() {
        0 => Err(CliError::user(format!(
            "--merge: no parts beside {} (render them with --shard I/N and the same -o: they are named {stem}.shard-I-of-N.png)",
            out.display()
        ))),
        1 => Ok(found.into_iter().map(|(_, _, p)| p).collect()),
        _ => Err(CliError::user(format!(
            "--merge: beside {} are parts of {} different shard counts ({}); delete the stale ones or name the parts with `strahl merge`",
            out.display(),
            counts.len(),
            counts.iter().map(u32::to_string).collect::<Vec<_>>().join(", ")
        ))),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn render() -> Render {
        Render {
            scene: "s.pov".into(),
            width: 3,
            height: 4,
            settings: Json::object(vec![("aa", Json::Number(1.0))]),
            clock: clock_json(&Clock::default()),
        }
    }

    /// Rows 0..4 of a 3-wide image, each row's bytes its row number.
    fn part(index: u32, count: u32, rows: Vec<Range<u32>>) -> (PathBuf, Part, Vec<u8>) {
        let rgb: Vec<u8> = rows.iter().flat_map(|r| r.clone()).flat_map(|y| [y as u8; 9]).collect();
        let p = Part { render: render(), shard: Shard { index, count }, rows, sha256: sha256_hex(&rgb) };
        (PathBuf::from(format!("p{index}.png")), p, rgb)
    }

    #[test]
    fn parts_join_into_the_whole() {
        let (r, rgb) = join(&[part(1, 2, vec![1..2, 3..4]), part(0, 2, vec![0..1, 2..3])], None).unwrap();
        assert_eq!(r, render());
        let rows: Vec<u8> = rgb.chunks(9).map(|c| c[0]).collect();
        assert_eq!(rows, vec![0, 1, 2, 3]);
    }

    #[test]
    fn join_refuses_mismatched_parts() {
        let err = |parts: &[(PathBuf, Part, Vec<u8>)]| join(parts, None).unwrap_err().message;
        assert!(err(&[part(0, 2, vec![0..2])]).contains("shard 1 of 2 is missing"));
        assert!(err(&[part(0, 2, vec![0..2]), part(0, 2, vec![2..4])]).contains("are both shard 0/2"));
        assert!(err(&[part(0, 2, vec![0..2]), part(1, 3, vec![2..4])]).contains("a part of 3 shards"));
        assert!(err(&[part(0, 2, vec![0..3]), part(1, 2, vec![2..4])]).contains("row 2 is in both"));
        assert!(err(&[part(0, 2, vec![0..1]), part(1, 2, vec![2..4])]).contains("no part has row 1 of 4"));
        let mut other = part(1, 2, vec![2..4]);
        other.1.render.width = 4;
        assert!(err(&[part(0, 2, vec![0..2]), other]).contains("another render"));
        let mut later = render();
        later.settings = Json::object(vec![("aa", Json::Number(2.0))]);
        let e = join(&[part(0, 1, vec![0..4])], Some(&later)).unwrap_err().message;
        assert!(e.contains("this command line") && e.contains("settings"), "{e}");
    }

    #[test]
    fn description_round_trips_and_names_are_beside_the_output() {
        let (_, p, _) = part(1, 2, vec![1..2, 3..4]);
        let back = Part::from_json(&Json::parse(&p.to_json().to_pretty()).unwrap()).unwrap();
        assert_eq!(back, p);
        let path = part_path(Path::new("out/poster.png"), Shard { index: 3, count: 8 });
        assert_eq!(path, Path::new("out/poster.shard-3-of-8.png"));
    }
}
