//! The camera path text format (see `docs/camera-paths.md`): one statement per line, `#` starts
//! a comment.
//!
//! ```text
//! spline centripetal          # or uniform (default centripetal)
//! constant_speed true         # reparameterise by arc length (default false)
//! closed true                 # a loop: last key repeats the first (default false)
//! key 0.0  location <6, 3, -2>  look_at <0, 1, 2>  angle 60
//! ```
//!
//! Every error is a `LocatedError` pointing at the offending word.

use glam::DVec3;

use crate::camera::path::{CameraPath, Key, Spline};
use crate::error::{visible, LocatedError};

/// A word of a line and its byte offset in the whole file.
#[derive(Clone, Copy, Debug)]
struct Word<'a> {
    text: &'a str,
    offset: usize,
}

/// Splits a line (comment already removed) into words; `<`, `>` and `,` are words of their own.
fn words(line: &str, line_offset: usize) -> Vec<Word<'_>> {
    let mut out = Vec::new();
    let mut start: Option<usize> = None;
    for (i, c) in line.char_indices() {
        let punct = matches!(c, '<' | '>' | ',');
        if c.is_whitespace() || punct {
            if let Some(s) = start.take() {
                out.push(Word { text: &line[s..i], offset: line_offset + s });
            }
            if punct {
                out.push(Word { text: &line[i..i + 1], offset: line_offset + i });
            }
        } else if start.is_none() {
            start = Some(i);
        }
    }
    if let Some(s) = start {
        out.push(Word { text: &line[s..], offset: line_offset + s });
    }
    out
}

struct Parser<'a> {
    file: &'a str,
    text: &'a str,
}

/// The words of one line, consumed left to right; `end` is the offset just past the line.
struct Cursor<'a> {
    words: Vec<Word<'a>>,
    pos: usize,
    end: usize,
}

impl<'a> Cursor<'a> {
    fn next(&mut self) -> Option<Word<'a>> {
        let w = self.words.get(self.pos).copied();
        self.pos += 1;
        w
    }
}

impl<'a> Parser<'a> {
    fn err(&self, offset: usize, message: impl Into<String>) -> LocatedError {
        LocatedError::at_offset(self.file, self.text, offset, message)
    }

    fn expect_word(&self, c: &mut Cursor<'a>, what: &str) -> Result<Word<'a>, LocatedError> {
        c.next().ok_or_else(|| self.err(c.end, format!("expected {what}, found end of line")))
    }

    fn number(&self, c: &mut Cursor<'a>, what: &str) -> Result<f64, LocatedError> {
        let w = self.expect_word(c, what)?;
        match w.text.parse::<f64>() {
            Ok(v) if v.is_finite() => Ok(v),
            Ok(_) => Err(self.err(w.offset, format!("{what} must be a finite number, found `{}`", visible(w.text)))),
            Err(_) => Err(self.err(w.offset, format!("bad number `{}` (expected {what})", visible(w.text)))),
        }
    }

    fn punct(&self, c: &mut Cursor<'a>, p: &str) -> Result<(), LocatedError> {
        let w = self.expect_word(c, &format!("`{p}`"))?;
        if w.text == p {
            Ok(())
        } else {
            Err(self.err(w.offset, format!("expected `{p}`, found `{}`", visible(w.text))))
        }
    }

    fn vector(&self, c: &mut Cursor<'a>, what: &str) -> Result<DVec3, LocatedError> {
        self.punct(c, "<")?;
        let x = self.number(c, &format!("{what} x"))?;
        self.punct(c, ",")?;
        let y = self.number(c, &format!("{what} y"))?;
        self.punct(c, ",")?;
        let z = self.number(c, &format!("{what} z"))?;
        self.punct(c, ">")?;
        Ok(DVec3::new(x, y, z))
    }

    fn boolean(&self, c: &mut Cursor<'a>, what: &str) -> Result<bool, LocatedError> {
        let w = self.expect_word(c, &format!("`true` or `false` after `{what}`"))?;
        match w.text {
            "true" | "on" | "yes" => Ok(true),
            "false" | "off" | "no" => Ok(false),
            other => {
                Err(self
                    .err(w.offset, format!("expected `true` or `false` after `{what}`, found `{}`", visible(other))))
            }
        }
    }

    fn key(&self, c: &mut Cursor<'a>, keyword: Word<'a>) -> Result<Key, LocatedError> {
        let time = self.number(c, "key time")?;
        let (mut location, mut look_at, mut angle) = (None, None, None);
        // Where the `look_at` vector starts, for the error when it is the location.
        let mut look_at_offset = c.end;
        while let Some(w) = c.next() {
            let seen = match w.text {
                "location" => location.replace(self.vector(c, "location")?).is_some(),
                "look_at" => {
                    look_at_offset = c.words.get(c.pos).map_or(c.end, |v| v.offset);
                    look_at.replace(self.vector(c, "look_at")?).is_some()
                }
                "angle" => {
                    let a = self.number(c, "angle")?;
                    if !(a > 0.0 && a < 180.0) {
                        return Err(self.err(w.offset, format!("angle must be between 0 and 180 degrees, found {a}")));
                    }
                    angle.replace(a).is_some()
                }
                other => {
                    return Err(self.err(
                        w.offset,
                        format!("unknown key field `{}` (supported: location, look_at, angle)", visible(other)),
                    ))
                }
            };
            if seen {
                return Err(self.err(w.offset, format!("`{}` given twice in one key", w.text)));
            }
        }
        let missing = |what: &str| self.err(keyword.offset, format!("key has no `{what}`"));
        let location = location.ok_or_else(|| missing("location"))?;
        let look_at = look_at.ok_or_else(|| missing("look_at"))?;
        if look_at == location {
            // The camera would have no direction; a scene's camera is refused the same way.
            return Err(self.err(look_at_offset, "camera look_at is the same point as its location"));
        }
        Ok(Key { time, location, look_at, angle })
    }
}

/// Settings given at most once, remembered with where they were given.
#[derive(Default)]
struct Settings {
    spline: Option<Spline>,
    constant_speed: Option<bool>,
    closed: Option<bool>,
}

pub(crate) fn parse(file: &str, text: &str) -> Result<CameraPath, LocatedError> {
    let p = Parser { file, text };
    let mut settings = Settings::default();
    // Each key with the offset of its `key` word, for errors found after the line is read.
    let mut keys: Vec<(Key, usize)> = Vec::new();
    let mut line_offset = 0;
    for raw in text.split_inclusive('\n') {
        let line = raw.split('#').next().unwrap_or("");
        let mut c = Cursor { words: words(line, line_offset), pos: 0, end: line_offset + line.trim_end().len() };
        line_offset += raw.len();
        let Some(first) = c.next() else { continue };
        let twice = |what: &str| p.err(first.offset, format!("`{what}` given twice"));
        match first.text {
            "key" => {
                let key = p.key(&mut c, first)?;
                if let Some((prev, _)) = keys.last() {
                    if key.time <= prev.time {
                        return Err(p.err(
                            first.offset,
                            format!("key times must increase: {} comes after {}", key.time, prev.time),
                        ));
                    }
                }
                keys.push((key, first.offset));
            }
            "spline" => {
                let w = p.expect_word(&mut c, "`centripetal` or `uniform`")?;
                let s = match w.text {
                    "centripetal" => Spline::Centripetal,
                    "uniform" => Spline::Uniform,
                    other => {
                        return Err(p.err(
                            w.offset,
                            format!("unknown spline `{}` (supported: centripetal, uniform)", visible(other)),
                        ))
                    }
                };
                if settings.spline.replace(s).is_some() {
                    return Err(twice("spline"));
                }
            }
            "constant_speed" => {
                if settings.constant_speed.replace(p.boolean(&mut c, "constant_speed")?).is_some() {
                    return Err(twice("constant_speed"));
                }
            }
            "closed" => {
                if settings.closed.replace(p.boolean(&mut c, "closed")?).is_some() {
                    return Err(twice("closed"));
                }
            }
            other => {
                return Err(p.err(
                    first.offset,
                    format!("unknown keyword `{}` (supported: key, spline, constant_speed, closed)", visible(other)),
                ))
            }
        }
        if let Some(extra) = c.next() {
            return Err(p.err(extra.offset, format!("unexpected `{}` at end of statement", visible(extra.text))));
        }
    }
    validate(&p, &keys, &settings)?;
    let closed = settings.closed.unwrap_or(false);
    Ok(CameraPath::new(
        keys.into_iter().map(|(k, _)| k).collect(),
        settings.spline.unwrap_or_default(),
        closed,
        settings.constant_speed.unwrap_or(false),
    ))
}

fn validate(p: &Parser, keys: &[(Key, usize)], settings: &Settings) -> Result<(), LocatedError> {
    if keys.len() < 2 {
        return Err(p.err(p.text.len(), format!("a camera path needs at least 2 keys, found {}", keys.len())));
    }
    let with_angle = keys.iter().filter(|(k, _)| k.angle.is_some()).count();
    if with_angle != 0 && with_angle != keys.len() {
        // Point at the first key that breaks the pattern the first key set.
        let first_has = keys[0].0.angle.is_some();
        if let Some((_, at)) = keys.iter().find(|(k, _)| k.angle.is_some() != first_has) {
            return Err(p.err(*at, "`angle` must be given on every key or on none"));
        }
    }
    if settings.closed == Some(true) {
        let (first, _) = &keys[0];
        let (last, at) = &keys[keys.len() - 1];
        let same = (last.location - first.location).length() < 1e-9
            && (last.look_at - first.look_at).length() < 1e-9
            && last.angle == first.angle;
        if !same {
            return Err(p.err(*at, "a closed path must end where it starts: the last key must repeat the first"));
        }
        if keys.len() < 3 {
            return Err(p.err(*at, "a closed path needs at least 3 keys (the last repeats the first)"));
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    const GOOD: &str = "# a path\nspline uniform\nconstant_speed false\n\
        key 0 location <0, 1, -5> look_at <0,0,0> angle 60 # start\n\
        key 2.5 location <5,1,0> look_at <0, 0, 0> angle 40\n";

    fn err(text: &str) -> LocatedError {
        match parse("p.path", text) {
            Ok(_) => panic!("expected an error for {text:?}"),
            Err(e) => e,
        }
    }

    #[test]
    fn parses_keys_and_settings() {
        let path = parse("p.path", GOOD).expect("valid path");
        assert_eq!(path.spline, Spline::Uniform);
        assert!(!path.constant_speed && !path.closed);
        assert_eq!(path.keys().len(), 2);
        assert_eq!(path.keys()[1].time, 2.5);
        assert_eq!(path.keys()[0].location, DVec3::new(0.0, 1.0, -5.0));
        assert_eq!(path.keys()[1].angle, Some(40.0));
    }

    #[test]
    fn unknown_keyword_is_located() {
        let e = err("key 0 location <0,0,0> look_at <1,1,1>\n  wobble 3\n");
        assert_eq!((e.line, e.col), (2, 3));
        assert!(e.message.contains("unknown keyword `wobble`"), "{}", e.message);
        assert!(e.to_string().ends_with("  wobble 3\n    ^"), "{e}");
    }

    #[test]
    fn unknown_key_field_is_located() {
        let e = err("key 0 location <0,0,0> lookat <1,1,1>\n");
        assert_eq!((e.line, e.col), (1, 24));
        assert!(e.message.contains("unknown key field `lookat`"));
    }

    #[test]
    fn bad_number_is_located() {
        let e = err("key 0 location <0,x1,0> look_at <1,1,1>\n");
        assert_eq!((e.line, e.col), (1, 19));
        assert!(e.message.contains("bad number `x1`"), "{}", e.message);
    }

    #[test]
    fn nan_and_infinity_are_rejected() {
        for (text, col) in [
            ("key nan location <0,0,0> look_at <1,1,1>\n", 5),
            ("key 0 location <0,0,inf> look_at <1,1,1>\n", 21),
            ("key 0 location <0,0,0> look_at <1e999,1,1>\n", 33),
            ("key 0 location <0,0,0> look_at <1,1,1> angle -inf\n", 46),
        ] {
            let e = err(text);
            assert_eq!((e.line, e.col), (1, col), "{text}");
            assert!(e.message.contains("finite"), "{}", e.message);
        }
    }

    #[test]
    fn key_with_look_at_equal_to_location_is_a_located_error() {
        let e = err("key 0 location <0,1,-5> look_at <0,0,0>\nkey 1 location <1,2,3>  look_at <1, 2, 3>\n");
        assert_eq!((e.line, e.col), (2, 33));
        assert_eq!(e.message, "camera look_at is the same point as its location");
    }

    #[test]
    fn invisible_characters_in_quoted_words_are_named() {
        let e = err(
            "key 0 location <0,0,0> look_at <1,1,1>\nkey 1 location <1,0,0> look_at <1,1,1>\n\u{200b}closed true\n",
        );
        assert_eq!((e.line, e.col), (3, 1));
        assert!(e.message.starts_with("unknown keyword `<U+200B>closed`"), "{}", e.message);
    }

    #[test]
    fn non_increasing_times_are_rejected() {
        let e = err("key 1 location <0,0,0> look_at <1,1,1>\nkey 1 location <1,0,0> look_at <1,1,1>\n");
        assert_eq!((e.line, e.col), (2, 1));
        assert!(e.message.contains("must increase"));
    }

    #[test]
    fn fewer_than_two_keys_is_rejected() {
        let e = err("# nothing\nkey 0 location <0,0,0> look_at <1,1,1>\n");
        assert!(e.message.contains("at least 2 keys, found 1"), "{}", e.message);
        assert!(err("").message.contains("found 0"));
    }

    #[test]
    fn missing_parts_are_rejected() {
        assert!(err("key 0 look_at <1,1,1>\nkey 1 location <0,0,0> look_at <1,1,1>\n")
            .message
            .contains("no `location`"));
        assert!(err("key 0 location <0,0,0 look_at <1,1,1>\n").message.contains("expected `>`, found `look_at`"));
        assert!(err("key 0 location <0,0,0> location <1,1,1>\n").message.contains("given twice"));
        assert!(err("key\n").message.contains("found end of line"));
        assert!(err("constant_speed maybe\n").message.contains("`true` or `false`"));
        assert!(err("spline bezier\n").message.contains("unknown spline `bezier`"));
        assert!(err("closed true\nclosed true\n").message.contains("given twice"));
        assert!(err("key 0 location <0,0,0> look_at <1,1,1> 7\n").message.contains("unknown key field `7`"));
        assert!(err("spline uniform extra\n").message.contains("unexpected `extra`"));
    }

    #[test]
    fn angle_on_some_keys_only_is_rejected() {
        let e = err("key 0 location <0,0,0> look_at <1,1,1> angle 50\nkey 1 location <1,0,0> look_at <1,1,1>\n");
        assert_eq!((e.line, e.col), (2, 1));
        assert!(e.message.contains("every key or on none"));
        assert!(err("key 0 location <0,0,0> look_at <1,1,1> angle 180\n").message.contains("between 0 and 180"));
    }

    #[test]
    fn closed_path_must_end_where_it_starts() {
        let e = err("closed true\nkey 0 location <0,0,0> look_at <1,1,1>\nkey 1 location <1,0,0> look_at <1,1,1>\nkey 2 location <2,0,0> look_at <1,1,1>\n");
        assert_eq!(e.line, 4);
        assert!(e.message.contains("end where it starts"));
    }

    #[test]
    fn shipped_paths_parse() {
        let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes");
        for name in ["seed.orbit.path", "seed.fly.path"] {
            let path = CameraPath::load(&dir.join(name)).unwrap_or_else(|e| panic!("{e}"));
            assert!(path.keys().len() >= 4, "{name}");
        }
    }

    #[test]
    fn shipped_orbit_ends_where_it_starts() {
        let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes");
        let path = CameraPath::load(&dir.join("seed.orbit.path")).unwrap_or_else(|e| panic!("{e}"));
        let (a, b) = (path.sample(0.0), path.sample(1.0));
        assert!((a.0 - b.0).length() < 1e-9 && (a.1 - b.1).length() < 1e-9);
        // It circles the objects: the camera stays 6..8 units from the orbit centre.
        for i in 0..=64 {
            let (loc, _, _) = path.sample(i as f64 / 64.0);
            let r = (loc - DVec3::new(0.0, loc.y, 2.5)).length();
            assert!((6.0..8.0).contains(&r), "radius {r} at {i}");
        }
    }

    #[test]
    fn shipped_fly_path_visits_the_hard_cases_without_entering_objects() {
        let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes");
        let path = CameraPath::load(&dir.join("seed.fly.path")).unwrap_or_else(|e| panic!("{e}"));
        let pts: Vec<DVec3> = (0..=2000).map(|i| path.sample(i as f64 / 2000.0).0).collect();
        let sphere_gap =
            pts.iter().map(|p| (*p - DVec3::new(0.0, 2.0, 4.0)).length() - 2.0).fold(f64::INFINITY, f64::min);
        assert!((0.3..1.0).contains(&sphere_gap), "closest to the sphere: {sphere_gap}");
        let lowest = pts.iter().map(|p| p.y).fold(f64::INFINITY, f64::min);
        assert!((0.15..0.5).contains(&lowest), "lowest: {lowest}");
        let farthest = pts.iter().map(|p| p.length()).fold(0.0, f64::max);
        assert!(farthest > 50.0, "farthest: {farthest}");
        // Never inside the box (its unrotated frame: x -1..1, y 0..2, z -0.5..1.5, turned -20° about y).
        let to_box = glam::DMat4::from_rotation_y((-20f64).to_radians()).inverse();
        for p in &pts {
            let q = to_box.transform_point3(*p);
            let inside = (-1.0..=1.0).contains(&q.x) && (0.0..=2.0).contains(&q.y) && (-0.5..=1.5).contains(&q.z);
            assert!(!inside, "inside the box at {p}");
        }
    }
}
