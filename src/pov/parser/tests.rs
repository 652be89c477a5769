//! Parser unit tests: grammar and syntax errors, read through the lowered scene (the parser
//! hands each item to `lower` as it reads it).

use glam::DVec3;

use crate::desc::{SceneDesc, ShapeDesc};
use crate::pov::lower::tests::lower;

fn parse_str(text: &str) -> Result<SceneDesc, String> {
    lower(text).map(|(scene, _)| scene)
}

#[test]
fn sphere_with_optional_commas() {
    let s = parse_str("sphere { <0,1,2> 3 }").unwrap();
    assert_eq!(s.objects[0].shape, ShapeDesc::Sphere { center: DVec3::new(0.0, 1.0, 2.0), radius: 3.0 });
}

#[test]
fn missing_argument_is_counted() {
    let e = parse_str("sphere { <0,0,0> pigment { color rgb 1 } }").unwrap_err();
    assert_eq!(e, "sphere needs 2 arguments (center, radius), found 1");
}

#[test]
fn unclosed_block_names_its_opener() {
    let e = parse_str("\n\n  sphere { <0,0,0>, 1\n").unwrap_err();
    assert_eq!(e, "expected `}` to close `sphere` opened at 3:3, found end of file");
}

#[test]
fn unknown_camera_keyword_lists_the_valid_ones() {
    let e = parse_str("camera { locaton <0,0,0> }").unwrap_err();
    assert_eq!(
        e,
        "unknown keyword `locaton` in camera (expected one of: location, look_at, angle, right, up, direction, sky)"
    );
}

#[test]
fn unsupported_shape_is_named() {
    let e = parse_str("sphere_sweep { linear_spline 2, 0, 1, y, 1 }").unwrap_err();
    assert_eq!(
        e,
        "`sphere_sweep` is not supported (supported: sphere, plane, box, triangle, polygon, cylinder, cone, disc, \
         torus, quadric, cubic, quartic, poly, superellipsoid, prism, text, lathe, sor, blob, julia_fractal, \
         smooth_triangle, mesh, mesh2, height_field, bicubic_patch, isosurface, parametric, light_group, union, merge, \
         intersection, difference, object)"
    );
}

#[test]
fn deep_nesting_is_an_error_not_a_stack_overflow() {
    let text = format!("#declare A = {}1{};", "(".repeat(100_000), ")".repeat(100_000));
    let e = parse_str(&text).unwrap_err();
    assert!(e.starts_with("nesting deeper than"), "{e}");
    let text = format!("#declare A = {}1;", "-".repeat(100_000));
    assert!(parse_str(&text).unwrap_err().starts_with("nesting deeper than"));
}

#[test]
fn keywords_cannot_be_declared() {
    assert_eq!(parse_str("#declare x = 1;").unwrap_err(), "cannot declare `x`: it is a keyword");
}

#[test]
fn union_objects_come_before_modifiers() {
    let e = parse_str("union { sphere { 0, 1 } pigment { rgb 1 } sphere { x, 1 } }").unwrap_err();
    assert_eq!(e, "`sphere` after the modifiers of `union`: its objects must come first (as in POV-Ray)");
}

#[test]
fn conditions_need_parentheses_and_allow_comparisons() {
    let s = parse_str(
        "#declare A = 1; #declare B = 0;\n#if (A <= 2 & !B) sphere { 0, 1 } #elseif (1) sphere { 0, 2 } #else sphere { 0, 3 } #end",
    )
    .unwrap();
    assert_eq!(s.objects.len(), 1);
    assert_eq!(s.objects[0].shape, ShapeDesc::Sphere { center: DVec3::ZERO, radius: 1.0 });
    // Outside parentheses `<` opens a vector, as in POV-Ray.
    assert!(parse_str("#declare A = 1 < 2;").is_err());
    assert!(parse_str("#declare V = <1, (2 > 1), 3>;").is_ok());
}

#[test]
fn deep_directive_nesting_is_capped() {
    // Open directive blocks are data, not recursion: 200 of them only lack their `#end`s.
    let text = "#if (1) ".repeat(200);
    assert_eq!(parse_str(&text).unwrap_err(), "`#if` is not closed by `#end` before the end of the scene file");
    let text = format!("#declare A = (1{});", " < 1".repeat(500));
    assert!(parse_str(&text).unwrap_err().contains("nesting deeper"));
}
