//! The capture manifest (`manifest.json`): what was rendered, from where, and the SHA-256 of
//! every frame's 8-bit pixels; plus merging the manifests of sharded captures.
//!
//! Timing (`render_ms`) is the one field that differs between two correct runs, so every
//! comparison here (`same_content`, merge conflict checks) leaves it out explicitly.

use std::path::Path;

use glam::DVec3;

use crate::camera::Camera;
use crate::headless::capture::ClockRange;
use crate::headless::json::Json;
use crate::headless::CliError;

pub const FORMAT: &str = "strahl-capture";
pub const VERSION: u64 = 1;

#[derive(Clone, Debug, PartialEq)]
pub struct CameraRecord {
    pub location: DVec3,
    /// The path's look_at point (not merely one direction length ahead).
    pub look_at: DVec3,
    pub direction: DVec3,
    pub right: DVec3,
    pub up: DVec3,
}

impl CameraRecord {
    pub fn new(camera: &Camera, look_at: DVec3) -> CameraRecord {
        CameraRecord {
            location: camera.location,
            look_at,
            direction: camera.direction,
            right: camera.right,
            up: camera.up,
        }
    }
}

#[derive(Clone, Debug, PartialEq)]
pub struct FrameRecord {
    pub index: u32,
    pub t: f64,
    /// File name relative to the manifest's folder.
    pub file: String,
    pub camera: CameraRecord,
    /// Lower-case hex SHA-256 of the interleaved 8-bit RGB pixels (not of the PNG bytes).
    pub sha256: String,
    /// Wall time of `render()` alone; excluded from every comparison.
    pub render_ms: f64,
}

impl FrameRecord {
    /// Equal in everything but timing.
    pub fn same_content(&self, other: &FrameRecord) -> bool {
        FrameRecord { render_ms: 0.0, ..self.clone() } == FrameRecord { render_ms: 0.0, ..other.clone() }
    }
}

#[derive(Clone, Debug, PartialEq)]
pub struct Manifest {
    pub scene: String,
    pub path: String,
    pub width: u32,
    pub height: u32,
    /// Frames in the whole capture; a shard lists only some of them.
    pub frame_count: u32,
    /// Everything that changes pixels besides the camera (quality, accelerator); opaque here.
    pub settings: Json,
    /// `--clock`: the frames' scenes were parsed at clocks from..to. Written only when given, so
    /// a capture without it keeps the manifest it always had.
    pub clock: Option<ClockRange>,
    /// Sorted by index.
    pub frames: Vec<FrameRecord>,
}

pub fn frame_file_name(index: u32) -> String {
    format!("frame_{index:04}.png")
}

impl Manifest {
    /// Equal in everything but timing.
    pub fn same_content(&self, other: &Manifest) -> bool {
        self.same_header(other)
            && self.frames.len() == other.frames.len()
            && self.frames.iter().zip(&other.frames).all(|(a, b)| a.same_content(b))
    }

    /// Of the same capture: scene, path, size, frame count, clock range and settings agree
    /// (frames may differ).
    pub fn same_header(&self, o: &Manifest) -> bool {
        (&self.scene, &self.path, self.width, self.height, self.frame_count, &self.settings, self.clock)
            == (&o.scene, &o.path, o.width, o.height, o.frame_count, &o.settings, o.clock)
    }

    pub fn to_json(&self) -> Json {
        let frames = self
            .frames
            .iter()
            .map(|f| {
                Json::object(vec![
                    ("index", Json::Number(f.index as f64)),
                    ("t", Json::Number(f.t)),
                    ("file", Json::str(&f.file)),
                    (
                        "camera",
                        Json::object(vec![
                            ("location", Json::vec3(f.camera.location)),
                            ("look_at", Json::vec3(f.camera.look_at)),
                            ("direction", Json::vec3(f.camera.direction)),
                            ("right", Json::vec3(f.camera.right)),
                            ("up", Json::vec3(f.camera.up)),
                        ]),
                    ),
                    ("sha256", Json::str(&f.sha256)),
                    ("render_ms", Json::Number(f.render_ms)),
                ])
            })
            .collect();
        let mut fields = vec![
            ("format", Json::str(FORMAT)),
            ("version", Json::Number(VERSION as f64)),
            ("scene", Json::str(&self.scene)),
            ("path", Json::str(&self.path)),
            ("width", Json::Number(self.width as f64)),
            ("height", Json::Number(self.height as f64)),
            ("frame_count", Json::Number(self.frame_count as f64)),
            ("settings", self.settings.clone()),
        ];
        if let Some(c) = self.clock {
            fields.push(("clock", c.to_json()));
        }
        fields.push(("frames", Json::Array(frames)));
        Json::object(fields)
    }

    pub fn from_json(v: &Json) -> Result<Manifest, String> {
        if v.get("format").and_then(Json::as_str) != Some(FORMAT)
            || v.get("version").and_then(Json::as_u64) != Some(VERSION)
        {
            return Err(format!("not a {FORMAT} manifest version {VERSION}"));
        }
        let field = |o: &Json, k: &str| o.get(k).cloned().ok_or_else(|| format!("missing `{k}`"));
        let string = |o: &Json, k: &str| {
            field(o, k)?.as_str().map(str::to_string).ok_or_else(|| format!("`{k}` is not a string"))
        };
        let int = |o: &Json, k: &str| {
            field(o, k)?
                .as_u64()
                .filter(|&n| n <= u32::MAX as u64)
                .map(|n| n as u32)
                .ok_or_else(|| format!("`{k}` is not a count"))
        };
        let vec3 = |o: &Json, k: &str| -> Result<DVec3, String> {
            let a = field(o, k)?;
            match a.as_array().map(|a| a.iter().map(Json::as_f64).collect::<Option<Vec<_>>>()) {
                Some(Some(c)) if c.len() == 3 => Ok(DVec3::new(c[0], c[1], c[2])),
                _ => Err(format!("`{k}` is not a 3-vector")),
            }
        };
        let number = |o: &Json, k: &str| field(o, k)?.as_f64().ok_or_else(|| format!("`{k}` is not a number"));
        let clock = match v.get("clock") {
            None | Some(Json::Null) => None,
            Some(c) => Some(ClockRange { from: number(c, "from")?, to: number(c, "to")? }),
        };
        let mut frames = Vec::new();
        for f in field(v, "frames")?.as_array().ok_or("`frames` is not an array")? {
            let cam = field(f, "camera")?;
            frames.push(FrameRecord {
                index: int(f, "index")?,
                t: number(f, "t")?,
                file: string(f, "file")?,
                camera: CameraRecord {
                    location: vec3(&cam, "location")?,
                    look_at: vec3(&cam, "look_at")?,
                    direction: vec3(&cam, "direction")?,
                    right: vec3(&cam, "right")?,
                    up: vec3(&cam, "up")?,
                },
                sha256: string(f, "sha256")?,
                // Timing is informative only; a missing or null value does not spoil a manifest.
                render_ms: f.get("render_ms").and_then(Json::as_f64).unwrap_or(f64::NAN),
            });
        }
        Ok(Manifest {
            scene: string(v, "scene")?,
            path: string(v, "path")?,
            width: int(v, "width")?,
            height: int(v, "height")?,
            frame_count: int(v, "frame_count")?,
            settings: field(v, "settings")?,
            clock,
            frames,
        })
    }

    /// Reads `dir/manifest.json`.
    pub fn read(dir: &Path) -> Result<Manifest, CliError> {
        let file = dir.join("manifest.json");
        let text = std::fs::read_to_string(&file)
            .map_err(|e| CliError::user(format!("{}: cannot read: {e}", file.display())))?;
        Json::parse(&text)
            .and_then(|j| Manifest::from_json(&j))
            .map_err(|e| CliError::user(format!("{}: bad manifest: {e}", file.display())))
    }

    /// Merges shard manifests of one capture into the manifest of the whole: the shards must
    /// agree on scene, path, size, frame count, clock range and settings, may not list a frame twice, and
    /// together must cover every frame.
    pub fn merge(parts: &[Manifest]) -> Result<Manifest, String> {
        let first = parts.first().ok_or("nothing to merge")?;
        let mut merged = Manifest { frames: Vec::new(), ..first.clone() };
        for (i, part) in parts.iter().enumerate() {
            if !part.same_header(first) {
                return Err(format!(
                    "shard {} is from a different capture (scene, path, size, frame count, clock range or settings differ)",
                    i + 1
                ));
            }
            merged.frames.extend(part.frames.iter().cloned());
        }
        merged.frames.sort_by_key(|f| f.index);
        if let Some(w) = merged.frames.windows(2).find(|w| w[0].index == w[1].index) {
            return Err(format!("frame {} is listed by more than one shard", w[0].index));
        }
        let missing: Vec<String> = (0..merged.frame_count)
            .filter(|i| merged.frames.binary_search_by_key(i, |f| f.index).is_err())
            .map(|i| i.to_string())
            .collect();
        if !missing.is_empty() {
            let shown = missing.iter().take(10).cloned().collect::<Vec<_>>().join(", ");
            let more = if missing.len() > 10 { format!(" and {} more", missing.len() - 10) } else { String::new() };
            return Err(format!("no shard has frame {shown}{more} of {}", merged.frame_count));
        }
        if let Some(f) = merged.frames.iter().find(|f| f.index >= merged.frame_count) {
            return Err(format!("frame {} is past the frame count {}", f.index, merged.frame_count));
        }
        Ok(merged)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn frame(index: u32, ms: f64) -> FrameRecord {
        FrameRecord {
            index,
            t: index as f64 / 3.0,
            file: frame_file_name(index),
            camera: CameraRecord {
                location: DVec3::new(0.1, 2.0, -3.0),
                look_at: DVec3::ZERO,
                direction: DVec3::Z,
                right: DVec3::X,
                up: DVec3::Y,
            },
            sha256: format!("{index:064x}"),
            render_ms: ms,
        }
    }

    fn manifest(frames: Vec<FrameRecord>) -> Manifest {
        Manifest {
            scene: "s.pov".into(),
            path: "p.path".into(),
            width: 8,
            height: 6,
            frame_count: 4,
            settings: Json::object(vec![("aa", Json::Number(1.0))]),
            clock: None,
            frames,
        }
    }

    #[test]
    fn json_round_trip() {
        let m = manifest((0..4).map(|i| frame(i, 1.25)).collect());
        let text = m.to_json().to_pretty();
        assert!(!text.contains("clock"), "no clock key without --clock: {text}");
        let back = Manifest::from_json(&Json::parse(&text).expect("parses")).expect("valid");
        assert_eq!(back, m);
        let clocked = Manifest { clock: Some(ClockRange { from: 0.1, to: -2.5 }), ..m };
        let back = Manifest::from_json(&Json::parse(&clocked.to_json().to_pretty()).expect("parses")).expect("valid");
        assert_eq!(back, clocked);
    }

    #[test]
    fn another_clock_range_is_another_capture() {
        let a = manifest(vec![frame(0, 1.0), frame(1, 1.0)]);
        let b =
            Manifest { clock: Some(ClockRange { from: 0.0, to: 1.0 }), ..manifest(vec![frame(2, 1.0), frame(3, 1.0)]) };
        assert!(!a.same_header(&b));
        assert!(Manifest::merge(&[a, b.clone()]).unwrap_err().contains("shard 2 is from a different capture"));
        let c = Manifest { clock: Some(ClockRange { from: 0.0, to: 2.0 }), ..b.clone() };
        assert!(!b.same_header(&c));
    }

    #[test]
    fn merged_shards_equal_the_whole_but_for_timing() {
        let whole = manifest((0..4).map(|i| frame(i, 1.0)).collect());
        let a = manifest(vec![frame(2, 5.0), frame(3, 5.0)]);
        let b = manifest(vec![frame(0, 7.0), frame(1, 7.0)]);
        let merged = Manifest::merge(&[a.clone(), b.clone()]).expect("merges");
        assert!(merged.same_content(&whole));
        assert_ne!(merged, whole, "timing differs, and only timing");
        let mut wrong = whole.clone();
        wrong.frames[1].sha256 = "0".repeat(64);
        assert!(!merged.same_content(&wrong));
    }

    #[test]
    fn merge_rejects_gaps_overlaps_and_strangers() {
        let a = manifest(vec![frame(0, 1.0), frame(1, 1.0)]);
        assert!(Manifest::merge(std::slice::from_ref(&a)).unwrap_err().contains("no shard has frame 2, 3 of 4"));
        let b = manifest(vec![frame(1, 1.0), frame(2, 1.0), frame(3, 1.0)]);
        assert!(Manifest::merge(&[a.clone(), b]).unwrap_err().contains("frame 1 is listed by more than one shard"));
        let mut c = manifest(vec![frame(2, 1.0), frame(3, 1.0)]);
        c.width = 9;
        assert!(Manifest::merge(&[a, c]).unwrap_err().contains("shard 2 is from a different capture"));
        assert!(Manifest::merge(&[]).is_err());
    }
}
