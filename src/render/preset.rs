//! Named speed/accuracy presets (`--preset fast|balanced|full|reference`): a resolution scale,
//! an antialiasing level and the `Quality` knobs, chosen from measured trade-offs.
//!
//! `full` renders exactly what the scene asks; `reference` is the best strahl renders (4×4
//! antialiasing, nearest hits re-solved in f64) and the image `strahl tradeoff` measures
//! every other setting against. `fast` and `balanced` are
//! points on the Pareto front that `strahl tradeoff` measured on the seed scene
//! (`docs/tradeoff/seed.md`). Explicit flags override a preset's fields in the CLI.

use std::fmt;
use std::str::FromStr;

use super::precision::Precision;
use super::Quality;

/// Focal-blur rays per sample under `fast` and `balanced` (`Quality::max_blur_samples`).
pub const FAST_BLUR_SAMPLES: u32 = 4;
pub const BALANCED_BLUR_SAMPLES: u32 = 16;

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Preset {
    Fast,
    Balanced,
    Full,
    Reference,
}

/// What a preset sets: the fraction of the output size to trace (upscaled back), N×N
/// antialiasing, and the quality knobs.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PresetSettings {
    pub res_scale: f32,
    pub aa: u32,
    pub quality: Quality,
}

impl Preset {
    pub const ALL: [Preset; 4] = [Preset::Fast, Preset::Balanced, Preset::Full, Preset::Reference];

    pub fn name(self) -> &'static str {
        match self {
            Preset::Fast => "fast",
            Preset::Balanced => "balanced",
            Preset::Full => "full",
            Preset::Reference => "reference",
        }
    }

    pub fn settings(self) -> PresetSettings {
        let full = PresetSettings { res_scale: 1.0, aa: 1, quality: Quality::default() };
        // `fast` and `balanced` are points of the Pareto front of (ms, 1 − SSIM) that
        // `strahl tradeoff scenes/seed.pov -W 640 -H 360 --repeats 9` measured (docs/tradeoff/seed.md,
        // 2 shared cores). The front is res-scale 0.25 (1.5 ms, 1 − SSIM 0.194), 0.5 (2.6 ms, 0.101),
        // 0.75 (4.4 ms, 0.064), aa 2 (24.2 ms, 0.035), aa 3 (54.0 ms, 0.026), reference (455 ms, 0);
        // `full` (6.2 ms, 0.0645) is off it, because the bilinear upscale of a 0.75 render smooths
        // the checker's aliasing about as much as it loses detail. No other knob reaches the front on
        // this scene: shadows off saves 14% for 1.44× the error, max_octaves 0 saves 14% for 1.12×,
        // max_trace_level changes nothing (no reflection or refraction), and precision f64 costs
        // 4.7× the time for no visible gain here (1 − SSIM 0.06451 against 0.06447).
        match self {
            // 2.4× faster than `full` for 1.6× its error (PSNR 21.8 dB vs 21.9): the last step of
            // the front before the error doubles with each halving of time (0.25 is 1.7× faster
            // again for 1.9× the error, and traces 160×90 pixels at 640×360).
            // Area lights: at most 4 shadow rays per light and point (2×2), so soft-shadow scenes
            // stay interactive; `balanced` allows 16 (4×4). Measured on scenes/area_light.pov
            // (docs/tradeoff/area_light.md). The seed scene has no area light.
            // Focal blur: 4 rays per pixel (scenes ask for 20-100), so a blurred scene stays
            // interactive in the window (scenes/focal_blur.pov: docs/perf/cameras.md).
            Preset::Fast => PresetSettings {
                res_scale: 0.5,
                quality: Quality {
                    max_blur_samples: Some(FAST_BLUR_SAMPLES),
                    max_area_samples: Some(4),
                    ..full.quality
                },
                ..full
            },
            // The knee of the front: 1.4× faster than `full` at its error (1 − SSIM 0.0642 vs
            // 0.0645, PSNR 23.8 dB vs 21.9). Beyond it, aa 2 costs 5.5× the time for 0.55× the error.
            Preset::Balanced => PresetSettings {
                res_scale: 0.75,
                quality: Quality {
                    max_blur_samples: Some(BALANCED_BLUR_SAMPLES),
                    max_area_samples: Some(16),
                    ..full.quality
                },
                ..full
            },
            Preset::Full => full,
            // 4×4 samples per pixel, hits re-solved in f64: strahl's best, and the reference
            // errors are measured against (docs/precision.md).
            Preset::Reference => {
                PresetSettings { aa: 4, quality: Quality { precision: Precision::F64, ..full.quality }, ..full }
            }
        }
    }
}

impl fmt::Display for Preset {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

impl FromStr for Preset {
    type Err = String;

    fn from_str(s: &str) -> Result<Preset, String> {
        Preset::ALL.into_iter().find(|p| p.name() == s).ok_or_else(|| {
            let names: Vec<&str> = Preset::ALL.iter().map(|p| p.name()).collect();
            format!("unknown preset `{s}` (presets: {})", names.join(", "))
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_round_trip() {
        for p in Preset::ALL {
            assert_eq!(p.name().parse::<Preset>(), Ok(p));
            assert_eq!(p.to_string(), p.name());
        }
        let e = "quick".parse::<Preset>().unwrap_err();
        assert!(e.contains("`quick`") && e.contains("fast, balanced, full, reference"), "{e}");
    }

    #[test]
    fn full_is_the_scene_and_reference_is_4x4_aa_in_f64() {
        let full = Preset::Full.settings();
        assert_eq!(full, PresetSettings { res_scale: 1.0, aa: 1, quality: Quality::default() });
        assert_eq!(full.quality.precision, Precision::F32);
        let reference = Preset::Reference.settings();
        assert_eq!(reference.quality.precision, Precision::F64);
        let f64_full = Quality { precision: Precision::F64, ..full.quality };
        assert_eq!(reference, PresetSettings { aa: 4, quality: f64_full, ..full });
        // Only `reference` traces in f64: the others are points of the f32 front.
        for p in [Preset::Fast, Preset::Balanced, Preset::Full] {
            assert_eq!(p.settings().quality.precision, Precision::F32, "{p}");
        }
    }

    #[test]
    fn cheaper_presets_are_cheaper() {
        // Pixels traced per output pixel: scale² × aa². Fast ≤ balanced ≤ full < reference.
        let cost = |p: Preset| {
            let s = p.settings();
            s.res_scale * s.res_scale * (s.aa * s.aa) as f32
        };
        assert!(cost(Preset::Fast) <= cost(Preset::Balanced));
        assert!(cost(Preset::Balanced) <= cost(Preset::Full));
        assert!(cost(Preset::Full) < cost(Preset::Reference));
    }
}
