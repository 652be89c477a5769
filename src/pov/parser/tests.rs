//! Parser unit tests: grammar shapes and syntax errors (evaluation is tested in `lower`).

use super::parse;
use crate::pov::ast::{ExprKind, ObjectKind, ShapeKind, Stmt};
use crate::pov::lexer::lex;

fn parse_str(text: &str) -> Result<Vec<Stmt>, String> {
    let tokens = lex(0, text).map_err(|d| d.message)?;
    parse(&tokens, text).map_err(|d| d.message)
}

#[test]
fn sphere_with_optional_commas() {
    let s = parse_str("sphere { <0,1,2> 3 }").unwrap();
    match &s[0] {
        Stmt::Object(o) => match &o.kind {
            ObjectKind::Shape(ShapeKind::Sphere, args) => {
                assert!(matches!(args[0].kind, ExprKind::Vector(_)));
                assert_eq!(args[1].kind, ExprKind::Number(3.0));
            }
            other => panic!("{other:?}"),
        },
        other => panic!("{other:?}"),
    }
}

#[test]
fn missing_argument_is_counted() {
    let e = parse_str("sphere { <0,0,0> pigment { color rgb 1 } }").unwrap_err();
    assert_eq!(e, "sphere needs 2 arguments (center, radius), found 1");
}

#[test]
fn unclosed_block_names_its_opener() {
    let e = parse_str("\n\n  sphere { <0,0,0>, 1\n").unwrap_err();
    assert_eq!(
        e,
        "expected `}` to close `sphere` opened at 3:3, found end of file"
    );
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
    let e = parse_str("torus { 1, 0.5 }").unwrap_err();
    assert_eq!(
        e,
        "`torus` is not supported (supported: sphere, plane, box, triangle, polygon, union, merge, object)"
    );
}

#[test]
fn deep_nesting_is_an_error_not_a_stack_overflow() {
    let text = format!(
        "#declare A = {}1{};",
        "(".repeat(100_000),
        ")".repeat(100_000)
    );
    let e = parse_str(&text).unwrap_err();
    assert!(e.starts_with("nesting deeper than"), "{e}");
    let text = format!("#declare A = {}1;", "-".repeat(100_000));
    assert!(parse_str(&text)
        .unwrap_err()
        .starts_with("nesting deeper than"));
}

#[test]
fn keywords_cannot_be_declared() {
    assert_eq!(
        parse_str("#declare x = 1;").unwrap_err(),
        "cannot declare `x`: it is a keyword"
    );
}
