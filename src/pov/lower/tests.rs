//! Lowering unit tests: expression evaluation, colour forms and transforms, on in-memory text.

use glam::{DMat4, DVec3};

use super::{Files, Lowerer, Output};
use crate::pov::ast::Stmt;
use crate::pov::lexer::lex;
use crate::pov::parser::parse;
use crate::pov::source::{Diag, FileId, PResult, Span};
use crate::scene::desc::{Color, SceneDesc, SourceRef};

/// No includes: these tests lower one string.
struct NoFiles;

impl Files for NoFiles {
    fn enter_include(&mut self, _: &str, _: Span, path_span: Span) -> PResult<(FileId, Vec<Stmt>)> {
        Err(Diag::new(path_span, "no includes in unit tests"))
    }
    fn leave_include(&mut self) {}
    fn source_ref(&self, _: Span) -> SourceRef {
        SourceRef::default()
    }
}

/// Lowers `text`, returning the scene and its warnings.
pub(super) fn lower(text: &str) -> Result<(SceneDesc, Vec<Diag>), String> {
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
pub(super) fn lower_with_output(text: &str) -> Result<(SceneDesc, Vec<Output>), String> {
    let tokens = lex(0, text).map_err(|d| d.message)?;
    let stmts = parse(&tokens, text).map_err(|d| d.message)?;
    let mut files = NoFiles;
    Lowerer::new(&mut files, &crate::pov::ParseOptions::default()).finish(&stmts).map_err(|d| d.message)
}

/// The colour of the first light, written as `light_source { 0 color <expr> }`.
fn color_of(expr: &str) -> Color {
    let (s, _) = lower(&format!("light_source {{ 0 color {expr} }} background {{ {expr} }}")).unwrap();
    s.background
}

#[test]
fn arithmetic_and_functions() {
    let (s, _) = lower("#declare A = (1 + 2) * -3 / 2;\nsphere { <A, sqrt(16), max(2, pow(2, 3))>, abs(-2) }").unwrap();
    assert_eq!(
        s.objects[0].shape,
        crate::scene::desc::ShapeDesc::Sphere { center: DVec3::new(-4.5, 4.0, 8.0), radius: 2.0 }
    );
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
    let m = s.objects[0].transform.matrix;
    // +y → (x 90°) +z → (z 90°) +z.
    assert!(m.transform_point3(DVec3::Y).abs_diff_eq(DVec3::Z, 1e-12));
    // +x → (x 90°) +x → (z 90°) +y.
    assert!(m.transform_point3(DVec3::X).abs_diff_eq(DVec3::Y, 1e-12));
}

#[test]
fn transforms_compose_left_to_right() {
    let (s, _) = lower("sphere { 0, 1 scale 2 translate x }").unwrap();
    let m = s.objects[0].transform.matrix;
    assert_eq!(m, DMat4::from_translation(DVec3::X) * DMat4::from_scale(DVec3::splat(2.0)));
    assert_eq!(m.transform_point3(DVec3::X), DVec3::new(3.0, 0.0, 0.0));
}

#[test]
fn scale_by_zero_warns_and_keeps_the_axis() {
    let (s, w) = lower("sphere { 0, 1 scale <2, 0, 1> }").unwrap();
    assert_eq!(s.objects[0].transform.matrix, DMat4::from_scale(DVec3::new(2.0, 1.0, 1.0)));
    assert_eq!(w.len(), 1);
}

#[test]
fn scale_0_warns_once_not_once_per_axis() {
    let (s, w) = lower("sphere { 0, 1 scale 0 }").unwrap();
    assert_eq!(s.objects[0].transform.matrix, DMat4::IDENTITY);
    assert_eq!(w.len(), 1, "{w:?}");
    assert_eq!(w[0].message, "Illegal Value: Scale by 0.0 (x, y, z). Changed to 1.0.");
    let (_, w) = lower("sphere { 0, 1 scale <2, 0, 1> }").unwrap();
    assert_eq!(w[0].message, "Illegal Value: Scale by 0.0 (y). Changed to 1.0.");
}

#[test]
fn local_and_declare_scopes() {
    let (s, _) = lower("#local R = 2;\n#declare R = 3;\nsphere { 0, R }").unwrap();
    assert_eq!(s.objects[0].shape, crate::scene::desc::ShapeDesc::Sphere { center: DVec3::ZERO, radius: 3.0 });
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
        "#declare P = pigment { wood color_map { [0.9 rgb 1] [0.1 rgb 0] } turbulence 0.1 scale 2 }\n\
         sphere { 0, 1 pigment { P octaves 4 translate x } }",
    )
    .unwrap();
    let p = &s.objects[0].texture.pigment;
    match &p.pattern {
        crate::scene::desc::PigmentPattern::Wood(m) => {
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
        crate::scene::desc::PigmentPattern::Wood(m) => {
            assert_eq!(m.len(), 4);
            assert_eq!((m[1].value, m[2].value), (0.6, 0.6));
            assert_eq!(m[0].color, Color::rgb(0.666, 0.312, 0.2));
            assert_eq!(m[3].color, Color::rgb(0.4, 0.133, 0.066));
        }
        other => panic!("{other:?}"),
    }
}
