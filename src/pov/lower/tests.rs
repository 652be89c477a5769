//! Lowering unit tests: expression evaluation, colour forms and transforms, on in-memory text.

use glam::{DMat4, DVec3};

use std::rc::Rc;

use super::{Files, Lowerer, Output};
use crate::desc::{Color, SceneDesc, SourceRef};
use crate::pov::source::{Diag, FileId, PResult, Span};

/// No includes: these tests lower one string.
struct NoFiles(String);

impl Files for NoFiles {
    fn enter_include(&mut self, _: &str, _: Span, path_span: Span) -> PResult<(FileId, Rc<str>)> {
        Err(Diag::new(path_span, "no includes in unit tests"))
    }
    fn leave_include(&mut self) {}
    fn file_exists(&self, _: &str) -> bool {
        false
    }
    fn data_path(&self, _: &str, _: bool) -> Result<std::path::PathBuf, String> {
        Err("no files in unit tests".into())
    }
    fn source_ref(&self, span: Span) -> SourceRef {
        let e = crate::error::LocatedError::at_offset("test", &self.0, span.start as usize, "");
        SourceRef { file: "".into(), line: e.line, col: e.col }
    }
}

/// Lowers `text`, returning the scene and its warnings.
pub(crate) fn lower(text: &str) -> Result<(SceneDesc, Vec<Diag>), String> {
    let (scene, output) = lower_with_output(text)?;
    let warnings = output
        .into_iter()
        .filter_map(|o| match o {
            Output::Warning(d) => Some(d),
            Output::Debug(_) => None,
        })
        .collect();
    Ok((scene, warnings))
}

/// Lowers `text`, returning the scene and everything it printed (`#debug` text too).
pub(crate) fn lower_with_output(text: &str) -> Result<(SceneDesc, Vec<Output>), String> {
    let mut files = NoFiles(text.to_string());
    let mut low = Lowerer::new(&mut files, &crate::pov::ParseOptions::default());
    let (result, _) = crate::pov::parser::run(&mut low, 0, Rc::from(text));
    result.map_err(|d| d.message)?;
    Ok(low.finish())
}

/// The colour of the first light, written as `light_source { 0 color <expr> }`.
fn color_of(expr: &str) -> Color {
    let (s, _) = lower(&format!("light_source {{ 0 color {expr} }} background {{ {expr} }}")).unwrap();
    s.background
}

#[test]
fn arithmetic_and_functions() {
    let (s, _) = lower("#declare A = (1 + 2) * -3 / 2;\nsphere { <A, sqrt(16), max(2, pow(2, 3))>, abs(-2) }").unwrap();
    assert_eq!(s.objects[0].shape, crate::desc::ShapeDesc::Sphere { center: DVec3::new(-4.5, 4.0, 8.0), radius: 2.0 });
}

#[test]
fn version_keyword_and_directive() {
    let (s, _) = lower("#declare V = version;\n#version 3.5;\n#declare W = version;\n#version V;").unwrap();
    assert_eq!(s.version, 3.7);
    let (s, _) = lower("#version 3.5;").unwrap();
    assert_eq!(s.version, 3.5);
}

#[test]
fn color_forms() {
    assert_eq!(color_of("rgb <1, 0.5, 0>"), Color::rgb(1.0, 0.5, 0.0));
    assert_eq!(color_of("rgb 0.25"), Color::rgb(0.25, 0.25, 0.25));
    let c = color_of("rgbf <1, 1, 1, 0.5>");
    assert_eq!((c.filter, c.transmit), (0.5, 0.0));
    let c = color_of("rgbt <1, 1, 1, 0.5>");
    assert_eq!((c.filter, c.transmit), (0.0, 0.5));
    let c = color_of("rgbft <1, 1, 1, 0.25, 0.5>");
    assert_eq!((c.filter, c.transmit), (0.25, 0.5));
    let c = color_of("red 1 green 0.5 transmit 0.3");
    assert_eq!(c, Color { rgb: DVec3::new(1.0, 0.5, 0.0), filter: 0.0, transmit: 0.3 });
    // POV-Ray promotes a bare float to all five components (checked with a render).
    let c = color_of("color 0.5");
    assert_eq!((c.rgb, c.filter, c.transmit), (DVec3::splat(0.5), 0.5, 0.5));
    assert_eq!(color_of("<0.1, 0.2, 0.3>"), Color::rgb(0.1, 0.2, 0.3));
    let c = color_of("(rgb 1) * 0.5 + rgbft <0, 0, 0, 0, 0.5>");
    assert_eq!((c.rgb, c.transmit), (DVec3::splat(0.5), 0.5));
}

#[test]
fn color_with_base_and_override() {
    let (s, _) = lower("#declare C = rgb <1, 0, 0>;\nbackground { color C filter 0.5 green 1 }").unwrap();
    assert_eq!(s.background, Color { rgb: DVec3::new(1.0, 1.0, 0.0), filter: 0.5, transmit: 0.0 });
}

#[test]
fn rotate_order_is_x_then_y_then_z() {
    let (s, _) = lower("sphere { 0, 1 rotate <90, 0, 90> }").unwrap();
    let m = s.objects[0].transform.matrix();
    // +y → (x 90°) +z → (z 90°) +z.
    assert!(m.transform_point3(DVec3::Y).abs_diff_eq(DVec3::Z, 1e-12));
    // +x → (x 90°) +x → (z 90°) +y.
    assert!(m.transform_point3(DVec3::X).abs_diff_eq(DVec3::Y, 1e-12));
}

#[test]
fn transforms_compose_left_to_right() {
    let (s, _) = lower("sphere { 0, 1 scale 2 translate x }").unwrap();
    let m = s.objects[0].transform.matrix();
    assert_eq!(m, DMat4::from_translation(DVec3::X) * DMat4::from_scale(DVec3::splat(2.0)));
    assert_eq!(m.transform_point3(DVec3::X), DVec3::new(3.0, 0.0, 0.0));
}

#[test]
fn scale_by_zero_warns_and_keeps_the_axis() {
    let (s, w) = lower("sphere { 0, 1 scale <2, 0, 1> }").unwrap();
    assert_eq!(s.objects[0].transform.matrix(), DMat4::from_scale(DVec3::new(2.0, 1.0, 1.0)));
    assert_eq!(w.len(), 1);
}

#[test]
fn scale_0_warns_once_not_once_per_axis() {
    let (s, w) = lower("sphere { 0, 1 scale 0 }").unwrap();
    assert_eq!(s.objects[0].transform.matrix(), DMat4::IDENTITY);
    assert_eq!(w.len(), 1, "{w:?}");
    assert_eq!(w[0].message, "Illegal Value: Scale by 0.0 (x, y, z). Changed to 1.0.");
    let (_, w) = lower("sphere { 0, 1 scale <2, 0, 1> }").unwrap();
    assert_eq!(w[0].message, "Illegal Value: Scale by 0.0 (y). Changed to 1.0.");
}

#[test]
fn local_and_declare_scopes() {
    let (s, _) = lower("#local R = 2;\n#declare R = 3;\nsphere { 0, R }").unwrap();
    assert_eq!(s.objects[0].shape, crate::desc::ShapeDesc::Sphere { center: DVec3::ZERO, radius: 3.0 });
}

#[test]
fn type_errors_name_both_sides() {
    assert_eq!(lower("sphere { 0, <1, 2> }").unwrap_err(), "expected a float, found a vector");
    assert_eq!(
        lower("#declare P = pigment { checker }\n#declare A = P + 1;").unwrap_err(),
        "cannot do arithmetic on a pigment"
    );
}

#[test]
fn look_at_along_sky_keeps_the_given_right_vector() {
    // POV-Ray 3.7 warns and renders with +x right and +z up here (checked by rendering).
    let (s, w) = lower("camera { location <0, 5, 0> look_at 0 }").unwrap();
    assert_eq!(w.len(), 1);
    assert!(w[0].message.contains("sky direction should be different"));
    let c = s.camera;
    assert!(c.direction.abs_diff_eq(-DVec3::Y, 1e-12));
    assert!(c.right.abs_diff_eq(DVec3::new(1.33, 0.0, 0.0), 1e-12));
    assert!(c.up.abs_diff_eq(DVec3::Z, 1e-12));
}

#[test]
fn camera_errors() {
    assert!(lower("camera { location <0, 5, 0> right y look_at 0 }").unwrap_err().contains("parallel to sky"));
    assert!(lower("camera { location 1 look_at 1 }").unwrap_err().contains("same point"));
    assert!(lower("camera { angle 180 }").unwrap_err().contains("between 0 and 180"));
}

#[test]
fn pigment_copies_then_modifies() {
    let (s, _) = lower(
        "#declare P = pigment { wood color_map { [0.1 rgb 0] [0.9 rgb 1] } turbulence 0.1 scale 2 }\n\
         sphere { 0, 1 pigment { P octaves 4 translate x } }",
    )
    .unwrap();
    let p = &s.objects[0].texture.pigment;
    match &p.pattern {
        crate::desc::PigmentPattern::Wood(m) => {
            assert_eq!((m[0].value, m[1].value), (0.1, 0.9))
        }
        other => panic!("{other:?}"),
    }
    let t = p.turbulence.unwrap();
    assert_eq!((t.amount, t.octaves), (DVec3::splat(0.1), 4));
    assert_eq!(p.transform.matrix, DMat4::from_translation(DVec3::X) * DMat4::from_scale(DVec3::splat(2.0)));
    // Without a map, wood uses POV-Ray's tan/brown default (measured by rendering).
    let (s, _) = lower("sphere { 0, 1 pigment { wood } }").unwrap();
    match &s.objects[0].texture.pigment.pattern {
        crate::desc::PigmentPattern::Wood(m) => {
            assert_eq!(m.len(), 4);
            assert_eq!((m[1].value, m[2].value), (0.6, 0.6));
            assert_eq!(m[0].color, Color::rgb(0.666, 0.312, 0.2));
            assert_eq!(m[3].color, Color::rgb(0.4, 0.133, 0.066));
        }
        other => panic!("{other:?}"),
    }
}

/// The wood map of the first object of `text`, as (value, r, g, b) rows.
fn wood_map(text: &str) -> Vec<(f64, f64, f64, f64)> {
    let (s, _) = lower(text).unwrap();
    match &s.objects[0].texture.pigment.pattern {
        crate::desc::PigmentPattern::Wood(m) => {
            m.iter().map(|e| (e.value, e.color.rgb.x, e.color.rgb.y, e.color.rgb.z)).collect()
        }
        other => panic!("{other:?}"),
    }
}

fn assert_near(got: &[(f64, f64, f64, f64)], want: &[(f64, f64, f64, f64)]) {
    let close = |a: &(f64, f64, f64, f64), b: &(f64, f64, f64, f64)| {
        [a.0 - b.0, a.1 - b.1, a.2 - b.2, a.3 - b.3].iter().all(|d| d.abs() < 1e-12)
    };
    assert!(got.len() == want.len() && got.iter().zip(want).all(|(a, b)| close(a, b)), "{got:?} != {want:?}");
}

fn wood_with(map: &str) -> String {
    format!("#declare R = rgb <1, 0, 0>;\n#declare B = rgb <0, 0, 1>;\nsphere {{ 0, 1 pigment {{ wood color_map {{ {map} }} }} }}")
}

#[test]
fn color_map_band_entries_become_two_points() {
    // POV-Ray 3.7 renders `[a, b color C1 color C2]` as C1 at a blending to C2 at b, comma
    // optional, mixable with `[v C]` entries; `colour` works too.
    let m = wood_map(&wood_with("[0.0, 0.5 color R color B] [0.5 1.0 colour rgb 1 colour rgb 0] [1 R]"));
    assert_eq!(
        m,
        vec![
            (0.0, 1.0, 0.0, 0.0),
            (0.5, 0.0, 0.0, 1.0),
            (0.5, 1.0, 1.0, 1.0),
            (1.0, 0.0, 0.0, 0.0),
            (1.0, 1.0, 0.0, 0.0)
        ]
    );
    // Colour keywords and a filter inside a band's colours, as woodmaps.inc writes them.
    let (s, _) = lower(
        "sphere { 0, 1 pigment { wood color_map { [0, 0.1 color red 0.8 green 0.6 blue 0.2 filter 0.5 \
         color rgbt <0.5, 0.3, 0.2, 0.25>] } } }",
    )
    .unwrap();
    let crate::desc::PigmentPattern::Wood(m) = &s.objects[0].texture.pigment.pattern else { panic!() };
    assert_eq!((m[0].color.filter, m[1].color.transmit, m[1].value), (0.5, 0.25, 0.1));
}

#[test]
fn color_map_band_errors_are_located() {
    // POV-Ray: "Expected 'color', colour identifier found instead".
    let e = lower(&wood_with("[0 0.5 color R B]")).unwrap_err();
    assert!(e.contains("expected `color` and the second colour"), "{e}");
    let e = lower(&wood_with("[0 0.5 color R color B")).unwrap_err();
    assert!(e.contains("to close the color_map entry"), "{e}");
    let e = lower(&wood_with("[0 R color R color B]")).unwrap_err();
    assert!(e.contains("expected a float, found a color"), "{e}");
}

#[test]
fn color_map_reads_entries_in_written_order_like_povray() {
    // Already in order: unchanged.
    assert_eq!(wood_map(&wood_with("[0.2 R] [0.7 B]")), vec![(0.2, 1.0, 0.0, 0.0), (0.7, 0.0, 0.0, 1.0)]);
    // `[0 R][0.8 B][0.3 G]` renders R→B up to 0.3, then G (POV-Ray 3.7, gradient x).
    let m = wood_map(&wood_with("[0 R] [0.8 B] [0.3 rgb <0, 1, 0>]"));
    assert_near(&m, &[(0.0, 1.0, 0.0, 0.0), (0.3, 0.625, 0.0, 0.375), (0.3, 0.0, 1.0, 0.0)]);
    // Overlapping bands: the second one's blend starts at its own 0.4, read from 0.6 on (the
    // render through POV-Ray and strahl agrees to 74 dB).
    let m = wood_map(&wood_with("[0 0.6 color R color B] [0.4 1 color rgb 1 color rgb 0]"));
    let g = 2.0 / 3.0;
    assert_near(&m, &[(0.0, 1.0, 0.0, 0.0), (0.6, 0.0, 0.0, 1.0), (0.6, g, g, g), (1.0, 0.0, 0.0, 0.0)]);
    // Descending: below 0.1 the first colour, from 0.1 on the last.
    assert_eq!(wood_map(&wood_with("[0.9 R] [0.1 B]")), vec![(0.1, 1.0, 0.0, 0.0), (0.1, 0.0, 0.0, 1.0)]);
    // Values outside 0–1 are accepted, as POV-Ray does.
    assert_eq!(wood_map(&wood_with("[-0.5 R] [1.5 B]")), vec![(-0.5, 1.0, 0.0, 0.0), (1.5, 0.0, 0.0, 1.0)]);
}

#[test]
fn declared_color_map_is_used_by_name() {
    let m = wood_map(
        "#declare M = color_map { [0.0, 0.5 color rgb 1 color rgb 0] }\n\
         #declare N = colour_map { M }\n\
         sphere { 0, 1 pigment { wood colour_map { N } } }",
    );
    assert_eq!(m, vec![(0.0, 1.0, 1.0, 1.0), (0.5, 0.0, 0.0, 0.0)]);
    // A declared wood pigment takes a new map by name (woods.inc's `P_WoodGrain1A color_map { M }`).
    let m = wood_map(
        "#declare P = pigment { wood scale 2 }\n#declare M = color_map { [0 rgb 1] [1 rgb 0] }\n\
         sphere { 0, 1 pigment { P color_map { M } } }",
    );
    assert_eq!(m, vec![(0.0, 1.0, 1.0, 1.0), (1.0, 0.0, 0.0, 0.0)]);
    let e = lower("#declare P = pigment { wood }\nsphere { 0, 1 pigment { wood color_map { P } } }").unwrap_err();
    assert!(e.contains("expected a declared color_map, found a pigment"), "{e}");
    let e = lower("sphere { 0, 1 pigment { wood color_map { M } } }").unwrap_err();
    assert!(e.contains("undefined identifier `M`"), "{e}");
    // POV-Ray refuses entries after a map's name ("Must have at least one color in color map").
    let e = lower("#declare M = color_map { [0 rgb 1] }\nsphere { 0, 1 pigment { wood color_map { M [1 rgb 0] } } }")
        .unwrap_err();
    assert!(e.contains("expected `}` to close `color_map`"), "{e}");
}

#[test]
fn unmodelled_features_are_noted_once_each_and_the_scene_loads() {
    let text = "#macro Rad() count 35 error_bound 1.8 #end
        global_settings { assumed_gamma 1 radiosity { Rad() #if (1) nearest_count 5 #end } photons { spacing 0.1 }
                          noise_generator 3 number_of_waves 4 charset utf8 hf_gray_16 max_intersections 64 }
        sphere { 0, 1 interior { ior 1.5 media { emission 1 density { spherical } } caustics 1 fade_power 2 }
                 photons { target } no_image no_reflection off no_radiosity }
        sphere { 2, 1 photons { target } radiosity { importance 0.5 } interior { media { } } }";
    let (scene, warnings) = lower(text).unwrap();
    let names: Vec<&str> = scene.unmodelled.iter().map(|f| f.name.as_str()).collect();
    assert_eq!(names, ["radiosity", "photons", "media", "caustics", "no_image"]);
    assert_eq!(warnings.len(), names.len(), "{warnings:?}");
    assert!(warnings[0].message.contains("`radiosity` is not modelled"), "{}", warnings[0].message);
    assert_eq!((scene.unmodelled[0].at.line, scene.unmodelled[0].at.col), (2, 43));
    assert_eq!(scene.objects.len(), 2);
    assert_eq!((scene.global.noise_generator, scene.global.number_of_waves), (3, 4));
    // Out-of-range settings are located errors, not silent clamps.
    assert!(lower("global_settings { noise_generator 4 }").unwrap_err().contains("1, 2 or 3"));
    // An unclosed unmodelled block is an error that names it.
    assert!(lower("global_settings { radiosity { count 3 }").unwrap_err().contains("global_settings"));
    assert!(lower("global_settings { radiosity { count 3 ").unwrap_err().contains("radiosity"));
}

#[test]
fn finish_items_beyond_the_chapter() {
    let (s, w) = lower(
        "sphere { 0, 1 finish { metallic phong 1 emission rgb <0.1, 0.2, 0.3> conserve_energy
                        reflection { 0.1, 0.8 fresnel falloff 2 exponent 0.5 metallic } diffuse albedo 0.4 } }
         sphere { 0, 1 finish { metallic 0.3 reflection 0.5 reflection_exponent 2 crand 0.1 irid { 0.3 thickness 0.2 } } }",
    )
    .unwrap();
    let f = &s.objects[0].texture.finish;
    assert_eq!((f.metallic, f.emission, f.conserve_energy), (1.0, DVec3::new(0.1, 0.2, 0.3), true));
    assert_eq!(
        (f.reflection_min, f.reflection, f.reflection_fresnel),
        (Some(DVec3::splat(0.1)), DVec3::splat(0.8), true)
    );
    assert_eq!((f.reflection_falloff, f.reflection_exponent, f.reflection_metallic), (2.0, 0.5, 1.0));
    assert!(f.albedo.diffuse && !f.albedo.phong);
    let g = &s.objects[1].texture.finish;
    assert_eq!((g.metallic, g.reflection_min, g.reflection_exponent), (0.3, None, 2.0));
    let names: Vec<&str> = s.unmodelled.iter().map(|f| f.name.as_str()).collect();
    assert_eq!(names, ["crand", "irid"], "{w:?}");
    let e = lower("sphere { 0, 1 finish { reflection { 0.1, 0.8 fresnell } } }").unwrap_err();
    assert!(e.contains("fresnell") && e.contains("reflection"), "{e}");
}
