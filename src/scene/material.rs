//! Render-ready surface description: pigment, normal perturbation, finish and interior, in f32.

use glam::{DMat4, Vec3};

use crate::desc::{FadeDesc, FinishDesc, InteriorDesc, PigmentPattern, TextureDesc, TexturePatternDesc};
use crate::lanes::Lane;
use crate::shading::normal::NormalF32;
use crate::shading::pigment::Pigment;

/// A shading exponent. Whole numbers up to 256 (POV-Ray's default `phong_size 40`, the seed's
/// `brilliance 1`, `roughness 0.05` → 20) are raised by repeated squaring, which costs a few
/// multiplies against `powf`'s ~160 instructions per call (measured with callgrind on the seed
/// scene, where it was 6% of all instructions); others fall back to `powf`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Exponent {
    One,
    Whole(u32),
    Real(f32),
}

impl Exponent {
    pub fn new(e: f64) -> Exponent {
        if e == 1.0 {
            Exponent::One
        } else if (0.0..=256.0).contains(&e) && e.fract() == 0.0 {
            Exponent::Whole(e as u32)
        } else {
            Exponent::Real(e as f32)
        }
    }

    /// `x` raised to this exponent, for `x` in (0, 1].
    #[inline]
    pub fn pow(self, x: f32) -> f32 {
        self.pow_lanes(x)
    }

    /// `pow` for one or eight lanes, with the same operations in the same order.
    #[inline(always)]
    pub fn pow_lanes<L: Lane>(self, x: L) -> L {
        match self {
            Exponent::One => x,
            Exponent::Whole(mut n) => {
                let (mut base, mut acc) = (x, L::splat(1.0));
                while n > 0 {
                    if n & 1 == 1 {
                        acc = acc * base;
                    }
                    base = base * base;
                    n >>= 1;
                }
                acc
            }
            Exponent::Real(e) => x.map(|v| v.powf(e)),
        }
    }
}

/// POV-Ray's finish, with exponents precomputed.
#[derive(Clone, Copy, Debug)]
pub struct Finish {
    pub ambient: Vec3,
    pub diffuse: f32,
    pub brilliance: Exponent,
    pub phong: f32,
    pub phong_size: Exponent,
    pub specular: f32,
    /// `1 / roughness`, the Blinn exponent of `specular`.
    pub specular_exponent: Exponent,
    /// The reflection, or its maximum when `variable` is set.
    pub reflection: Vec3,
    /// How far highlights take the pigment's colour (`metallic`); 0 leaves them the light's.
    pub metallic: f32,
    pub emission: Vec3,
    /// Angle-dependent reflection (`reflection { MIN, MAX .. }`, `metallic`, `exponent`);
    /// `None` for a constant `reflection`, which is all the seed scene has.
    pub variable: Option<VariableReflection>,
    /// `conserve_energy`: filter and transmit are scaled by what reflection leaves.
    pub conserve_energy: bool,
}

/// The parts of `reflection { }` beyond one colour.
#[derive(Clone, Copy, Debug)]
pub struct VariableReflection {
    /// Seen along the normal (`Finish::reflection` at grazing angles).
    pub min: Vec3,
    pub falloff: f32,
    pub fresnel: bool,
    pub exponent: f32,
    pub metallic: f32,
}

/// A peak value for a lobe `cos^e` that reflects `albedo` in total: the lobe's integral over
/// the hemisphere, divided by the Lambertian one (π), is 2 / (e + 1), which is 1 for a plain
/// `diffuse` (brilliance 1), where POV-Ray's docs say `albedo` changes nothing.
fn peak_from_albedo(albedo: f64, exponent: f64) -> f64 {
    albedo * (exponent + 1.0) / 2.0
}

/// The Fresnel reflectance of unpolarised light arriving at `cos_i` onto a surface between air
/// and `ior` (either side), 1 under total internal reflection.
pub fn fresnel(cos_i: f32, ior: f32) -> f32 {
    let cos_i = cos_i.clamp(0.0, 1.0);
    let sin_t2 = (1.0 - cos_i * cos_i) / (ior * ior);
    if sin_t2 >= 1.0 {
        return 1.0;
    }
    let cos_t = (1.0 - sin_t2).sqrt();
    let rs = (cos_i - ior * cos_t) / (cos_i + ior * cos_t);
    let rp = (ior * cos_i - cos_t) / (ior * cos_i + cos_t);
    0.5 * (rs * rs + rp * rp)
}

impl Finish {
    pub fn from_desc(f: &FinishDesc) -> Finish {
        let roughness_exponent = 1.0 / f.roughness.max(1e-6);
        let diffuse = if f.albedo.diffuse { peak_from_albedo(f.diffuse, f.brilliance) } else { f.diffuse };
        let phong = if f.albedo.phong { peak_from_albedo(f.phong, f.phong_size) } else { f.phong };
        let specular = if f.albedo.specular { peak_from_albedo(f.specular, roughness_exponent) } else { f.specular };
        let variable = (f.reflection_min.is_some() || f.reflection_exponent != 1.0 || f.reflection_metallic != 0.0)
            .then(|| VariableReflection {
                min: f.reflection_min.unwrap_or(f.reflection).as_vec3(),
                falloff: f.reflection_falloff as f32,
                fresnel: f.reflection_fresnel,
                exponent: f.reflection_exponent as f32,
                metallic: f.reflection_metallic as f32,
            });
        Finish {
            ambient: f.ambient.as_vec3(),
            diffuse: diffuse as f32,
            brilliance: Exponent::new(f.brilliance),
            phong: phong as f32,
            phong_size: Exponent::new(f.phong_size),
            specular: specular as f32,
            specular_exponent: Exponent::new(roughness_exponent),
            reflection: f.reflection.as_vec3(),
            metallic: f.metallic as f32,
            emission: f.emission.as_vec3(),
            variable,
            conserve_energy: f.conserve_energy,
        }
    }

    pub fn reflects(&self) -> bool {
        self.reflection.max_element() > 0.0 || self.variable.as_ref().is_some_and(|v| v.min.max_element() > 0.0)
    }

    /// The reflection at a hit seen at `cos_i` (between the ray and the normal) on a surface of
    /// colour `color` whose interior has index `ior`, and the `exponent` of reflected light.
    pub fn reflection_at(&self, cos_i: f32, color: Vec3, ior: f32) -> (Vec3, f32) {
        let Some(v) = &self.variable else { return (self.reflection, 1.0) };
        let blend = if v.fresnel { fresnel(cos_i, ior) } else { (1.0 - cos_i).clamp(0.0, 1.0).powf(v.falloff) };
        let mut r = v.min.lerp(self.reflection, blend);
        if v.metallic > 0.0 {
            // The metal's colour along the normal, the light's at grazing angles (Fresnel-like).
            let grazing = (1.0 - cos_i).clamp(0.0, 1.0).powi(5);
            let tint = Vec3::ONE.lerp(color, v.metallic).lerp(Vec3::ONE, grazing);
            r *= tint;
        }
        (r, v.exponent)
    }
}

#[cfg(test)]
mod tests {
    use super::{Blend, Exponent, Material, Select};
    use crate::desc::{InteriorDesc, TextureDesc};

    fn blend(select: Select, n: usize) -> Blend {
        let m = Material::from_desc(&TextureDesc::default(), &InteriorDesc::default(), &glam::DMat4::IDENTITY);
        Blend { selector: m.pigment.clone(), select, entries: vec![m; n] }
    }

    fn weights(b: &Blend, v: f32) -> Vec<(usize, f32)> {
        let mut out = Vec::new();
        b.for_each_weight(v, |i, w| out.push((i, w)));
        out
    }

    #[test]
    fn a_map_blends_the_two_entries_around_the_value_and_clamps() {
        let b = blend(Select::Map(vec![0.2, 0.6, 0.6, 1.0]), 4);
        assert_eq!(weights(&b, -1.0), [(0, 1.0)]);
        assert_eq!(weights(&b, 0.2), [(0, 1.0)]);
        let w = weights(&b, 0.5);
        assert_eq!((w[0].0, w[1].0), (0, 1));
        assert!((w[0].1 - 0.25).abs() < 1e-6 && (w[1].1 - 0.75).abs() < 1e-6, "{w:?}");
        // A repeated value is a hard step to the upper entry.
        assert_eq!(weights(&b, 0.6), [(1, 1.0)]);
        assert_eq!(weights(&b, 0.8).iter().map(|e| e.0).collect::<Vec<_>>(), [2, 3]);
        assert_eq!(weights(&b, 7.0), [(3, 1.0)]);
        // A value a rounding away from an entry shades that entry alone.
        assert_eq!(weights(&b, 0.6 - 1e-7), [(1, 1.0)]);
    }

    #[test]
    fn a_list_picks_the_cell_and_average_weighs_them_all() {
        let b = blend(Select::List, 3);
        assert_eq!(weights(&b, 0.0), [(0, 1.0)]);
        assert_eq!(weights(&b, 1.0), [(1, 1.0)]);
        assert_eq!(weights(&b, 2.0), [(2, 1.0)]);
        let a = blend(Select::Average(vec![1.0, 3.0]), 2);
        assert_eq!(weights(&a, 0.3), [(0, 0.25), (1, 0.75)]);
    }

    #[test]
    fn whole_exponents_match_powf_closely() {
        for e in [0.0, 1.0, 2.0, 20.0, 40.0, 255.0, 2.5] {
            for x in [0.001f32, 0.3, 0.77, 0.999, 1.0] {
                let want = x.powf(e as f32);
                let got = Exponent::new(e).pow(x);
                assert!((got - want).abs() <= 1e-5 * want.max(1e-30) + 1e-30, "{x}^{e}: {got} vs {want}");
            }
        }
    }
}

/// Light fading along the distance it travels inside an object (POV-Ray 3.4.8.1.6
/// Attenuation), measured against POV-Ray 3.7 through slabs of known thickness: a fraction
/// `a = 1 / (1 + (d / distance)^power)` of the light passes, the rest turns into the fade
/// colour, `F + (1 − F)·a` per channel; from power 1000 on the fall-off is exponential,
/// `exp(−(1 − F)·d / distance)`.
#[derive(Clone, Copy, Debug)]
pub struct Fade {
    pub distance: f32,
    pub power: f32,
    pub color: Vec3,
}

impl Fade {
    /// `unit`: world units per render unit, which distances inside are measured in.
    fn from_desc(d: &FadeDesc, unit: f64) -> Fade {
        Fade { distance: (d.distance / unit) as f32, power: d.power as f32, color: d.color.as_vec3() }
    }

    /// What passes of light that travelled `d` inside.
    pub fn attenuation(&self, d: f32) -> Vec3 {
        let x = d / self.distance;
        if self.power >= 1000.0 {
            return ((self.color - Vec3::ONE) * x).exp();
        }
        let a = 1.0 / (1.0 + x.powf(self.power));
        self.color + (Vec3::ONE - self.color) * a
    }
}

#[derive(Clone, Debug)]
pub struct Material {
    pub pigment: Pigment,
    pub normal: Option<NormalF32>,
    pub finish: Finish,
    pub ior: f32,
    /// How light fades travelling through the object, if it does.
    pub fade: Option<Fade>,
    /// Which of the scene's lights light this surface (`light_group`), by light index; `None`
    /// (every scene without light groups): all of them.
    pub lights: Option<std::sync::Arc<[bool]>>,
    /// `uv_mapping`: where the pigment is evaluated on this object's surface (one material per
    /// uv-mapped object); `None` for 3-D pattern space.
    pub uv: Option<Box<crate::geometry::uv::UvMap>>,
    /// A pattern of materials that differ in normal or finish (`TexturePatternDesc`): each
    /// hit is shaded as the entries it shows. `None` for every plain texture.
    pub blend: Option<Box<Blend>>,
    /// `interior_texture`: the material (an index into the scene's materials) a ray sees where
    /// it meets the surface from inside. `None`: this one on both sides.
    pub inside: Option<u32>,
}

/// A pattern of whole materials; `Material::pigment` holds the same pattern over their
/// pigments.
#[derive(Clone, Debug)]
pub struct Blend {
    /// Its pattern value (`shading::pigment::pattern_value`) picks the entries.
    pub selector: Pigment,
    pub select: Select,
    pub entries: Vec<Material>,
}

/// How a pattern value picks `Blend` entries, as the pigment of the same pattern blends.
#[derive(Clone, Debug, PartialEq)]
pub enum Select {
    /// A map's entry values, sorted: blends the two around the value, clamped at both ends.
    Map(Vec<f32>),
    /// `average`: every entry by its weight.
    Average(Vec<f32>),
    /// A list pattern: the value is the cell's index.
    List,
    /// Layered textures: the entries are the layers, bottom first, each shaded with its own
    /// finish (`Tracer::shade_layers`); no pattern picks them.
    Layers,
}

/// Weights below this do not get an entry shaded (a value a rounding away from an entry).
const NEGLIGIBLE_WEIGHT: f32 = 1e-4;

impl Blend {
    fn from_desc(d: &TexturePatternDesc, interior: &InteriorDesc, world_from_render: &DMat4) -> Blend {
        let selector = Pigment::from_desc(&d.selector, world_from_render);
        let select = match &d.selector.pattern {
            _ if d.layered => Select::Layers,
            PigmentPattern::PigmentMap(pd, e) if matches!(pd.kind, crate::desc::PatternKind::Average) => {
                Select::Average(e.iter().map(|(w, _)| *w as f32).collect())
            }
            PigmentPattern::PigmentMap(_, e) => Select::Map(e.iter().map(|(v, _)| *v as f32).collect()),
            _ => Select::List,
        };
        let entries = d.entries.iter().map(|t| Material::from_desc(t, interior, world_from_render)).collect();
        Blend { selector, select, entries }
    }

    /// Calls `f(entry, weight)` for each entry that shows at pattern value `v`; the weights
    /// sum to 1 (to rounding), as `shading::pigment` blends the same pattern's pigments.
    pub fn for_each_weight(&self, v: f32, mut f: impl FnMut(usize, f32)) {
        let n = self.entries.len();
        if n == 0 {
            return;
        }
        match &self.select {
            // Not a weighting: `Tracer::shade_layers` shades every layer that shows.
            Select::Layers => f(0, 1.0),
            Select::List => {
                let k = (1..n).rev().find(|&k| k as f32 - 0.5 < v).unwrap_or(0);
                f(k, 1.0);
            }
            Select::Average(w) => {
                let total: f32 = w.iter().sum();
                for (i, w) in w.iter().enumerate().take(n) {
                    if total != 0.0 && *w / total >= NEGLIGIBLE_WEIGHT {
                        f(i, w / total);
                    }
                }
            }
            Select::Map(values) => {
                let last = values.len().min(n) - 1;
                if v <= values[0] {
                    return f(0, 1.0);
                }
                for i in 1..=last {
                    let (v0, v1) = (values[i - 1], values[i]);
                    if v <= v1 {
                        let span = v1 - v0;
                        let t = if span > 0.0 { (v - v0) / span } else { 1.0 };
                        if t < NEGLIGIBLE_WEIGHT {
                            f(i - 1, 1.0);
                        } else if 1.0 - t < NEGLIGIBLE_WEIGHT {
                            f(i, 1.0);
                        } else {
                            f(i - 1, 1.0 - t);
                            f(i, t);
                        }
                        return;
                    }
                }
                f(last, 1.0)
            }
        }
    }
}

impl Material {
    /// Whether light `index` of the scene lights this surface.
    #[inline]
    pub fn lit_by(&self, index: usize) -> bool {
        self.lights.as_ref().is_none_or(|mask| mask[index])
    }

    /// Whether any point of the pigment lets light through (filter or transmit above zero).
    pub fn may_be_transparent(&self) -> bool {
        self.pigment.pattern.may_be_transparent()
    }

    /// Whether the local model covers this material: no reflection or transparency (recursive
    /// rays), no uv mapping, layers or interior texture. Packets shade such materials eight
    /// lanes wide (`Scene::local`).
    pub fn is_local(&self) -> bool {
        !self.finish.reflects()
            && !self.may_be_transparent()
            && self.uv.is_none()
            && self.blend.is_none()
            && self.inside.is_none()
    }

    /// `world_from_render`: `RenderFrame::world_from_render` of the scene being built.
    pub fn from_desc(texture: &TextureDesc, interior: &InteriorDesc, world_from_render: &DMat4) -> Material {
        Material {
            pigment: Pigment::from_desc(&texture.pigment, world_from_render),
            normal: texture.normal.as_ref().map(|n| NormalF32::from_desc(n, world_from_render)),
            finish: Finish::from_desc(&texture.finish),
            ior: interior.ior as f32,
            fade: interior.fade.as_deref().map(|f| Fade::from_desc(f, world_from_render.x_axis.truncate().length())),
            lights: None,
            uv: None,
            blend: texture.pattern.as_ref().map(|p| Box::new(Blend::from_desc(p, interior, world_from_render))),
            inside: None,
        }
    }

    /// Gives this material, and every material of its pattern, the surface mapping and the
    /// lights of the object that wears it.
    pub fn place(&mut self, uv: Option<Box<crate::geometry::uv::UvMap>>, lights: Option<std::sync::Arc<[bool]>>) {
        if let Some(b) = &mut self.blend {
            b.entries.iter_mut().for_each(|m| m.place(uv.clone(), lights.clone()));
        }
        self.uv = uv;
        self.lights = lights;
    }

    /// Whether it, or any material of its pattern, reflects.
    pub fn reflects(&self) -> bool {
        self.finish.reflects() || self.blend.as_ref().is_some_and(|b| b.entries.iter().any(Material::reflects))
    }

    /// Whether it, or any material of its pattern, perturbs its normals.
    pub fn has_normal(&self) -> bool {
        self.normal.is_some() || self.blend.as_ref().is_some_and(|b| b.entries.iter().any(Material::has_normal))
    }
}
