//! Lowering unit tests for the language added on top of the first subset: comparisons and logic,
//! `#if`/`#while`/`#switch`, renderer-provided values, `union`/`merge`, shadow flags.

use glam::{DMat4, DVec3};

use super::tests::{lower, lower_with_output};
use super::Output;
use crate::desc::{Color, PigmentPattern, ShapeDesc};

/// The float `expr` evaluates to, read back through a sphere radius offset.
fn value_of(expr: &str) -> f64 {
    let (s, _) = lower(&format!("#declare R = {expr};\nsphere {{ 0, R + 100 }}")).unwrap();
    match s.objects[0].shape {
        ShapeDesc::Sphere { radius, .. } => radius - 100.0,
        ref other => panic!("{other:?}"),
    }
}

fn radii(text: &str) -> Vec<f64> {
    let (s, _) = lower(text).unwrap();
    s.objects
        .iter()
        .map(|o| match o.shape {
            ShapeDesc::Sphere { radius, .. } => radius,
            _ => -1.0,
        })
        .collect()
}

#[test]
fn comparisons_and_logic_inside_parentheses() {
    // Each expected value was printed by POV-Ray 3.7 with `#debug`.
    assert_eq!(value_of("(1 < 2) + 5"), 6.0);
    assert_eq!(value_of("(1 = 1)"), 1.0);
    assert_eq!(value_of("(1 != 1)"), 0.0);
    assert_eq!(value_of("(2 >= 2) + (2 <= 1)"), 1.0);
    assert_eq!(value_of("(2 > 1 & 0 | 1)"), 1.0);
    assert_eq!(value_of("(1 | 0 & 0)"), 0.0, "& and | share one level");
    assert_eq!(value_of("(0 & 0 = 0)"), 0.0, "comparisons bind tighter");
    assert_eq!(value_of("(3 < 2 < 1)"), 1.0, "left to right");
    assert_eq!(value_of("(1 + 1 = 2)"), 1.0);
    assert_eq!(value_of("(0.5 & 2)"), 1.0);
    assert_eq!(value_of("(1e-11 = 0)"), 1.0, "POV-Ray's epsilon");
    assert_eq!(value_of("!0 + 1"), 2.0);
    assert_eq!(value_of("-!0"), -1.0);
    assert_eq!(value_of("(1 < 2 ? 5 : 6)"), 5.0);
    assert_eq!(value_of("(1 ? 2 : 3 ? 4 : 5)"), 2.0);
}

#[test]
fn comparison_outside_parentheses_is_rejected_like_povray() {
    // POV-Ray: "All #declares of float, vector, and color require semi-colon" at the `<`.
    assert!(lower("#declare A = 1 < 2;").is_err());
    assert!(lower("#declare A = (1 < <1,2,3>);").unwrap_err().contains("expected a float, found a vector"));
}

#[test]
fn vector_components() {
    assert_eq!(value_of("<1, 2, 3>.y + <1, 2, 3>.z"), 5.0);
    assert_eq!(value_of("(rgbft <0.1, 0.2, 0.3, 0.4, 0.5>).transmit"), 0.5);
    assert!(lower("#declare A = <1, 2>.z;").unwrap_err().contains("at least 3"));
    assert!(lower("#declare A = (1).x;").unwrap_err().contains("needs a vector"));
}

#[test]
fn image_size_and_clock() {
    assert!((value_of("image_width / image_height") - 640.0 / 480.0).abs() < 1e-9);
    assert_eq!(value_of("clock + clock_delta + frame_number"), 0.0);
    assert_eq!(value_of("initial_clock + final_clock"), 0.0);
}

#[test]
fn if_elseif_else() {
    let pick = |n: i32| {
        radii(&format!(
            "#declare N = {n};\n#if (N = 1) sphere {{ 0, 1 }}\n#elseif (N = 2) sphere {{ 0, 2 }}\n\
             #else sphere {{ 0, 3 }} #end"
        ))
    };
    assert_eq!((pick(1), pick(2), pick(7)), (vec![1.0], vec![2.0], vec![3.0]));
    assert_eq!(radii("#if (0) sphere { 0, 1 } #end"), Vec::<f64>::new());
    assert_eq!(radii("#ifndef (Q) sphere { 0, 1 } #else sphere { 0, 2 } #end"), vec![1.0]);
}

#[test]
fn while_builds_a_grid_of_spheres() {
    let (s, _) = lower(
        "#declare I = 0;\n#while (I < 10)\n #declare J = 0;\n #while (J < 10)\n  \
         #declare K = 0;\n  #while (K < 10)\n   sphere { <I, J, K>, 0.3 }\n   \
         #declare K = K + 1;\n  #end\n  #declare J = J + 1;\n #end\n #declare I = I + 1;\n#end",
    )
    .unwrap();
    assert_eq!(s.objects.len(), 1000);
    assert_eq!(s.objects[999].shape, ShapeDesc::Sphere { center: DVec3::splat(9.0), radius: 0.3 });
}

#[test]
fn endless_while_is_an_error() {
    let e = lower("#declare I = 0;\n#while (1) #declare I = I + 1; #end").unwrap_err();
    assert!(e.contains("more than 10000000 iterations"), "{e}");
}

#[test]
fn switch_falls_through_until_break() {
    // POV-Ray 3.7 gives R = 5 for this (#case 2 runs on into #case 3).
    let text = |v: f64| {
        format!(
            "#declare R = 0;\n#switch ({v})\n #case (1) #declare R = 1; #break\n \
             #case (2) #declare R = 2;\n #case (3) #declare R = R + 3; #break\n \
             #range (4, 6) #declare R = 4; #break\n #else #declare R = 9;\n#end\n\
             sphere {{ 0, R + 100 }}"
        )
    };
    let r = |v| radii(&text(v))[0] - 100.0;
    assert_eq!((r(1.0), r(2.0), r(3.0), r(6.0), r(7.0)), (1.0, 5.0, 3.0, 4.0, 9.0));
    assert_eq!(radii("#switch (7) #case (1) sphere { 0, 1 } #end"), Vec::<f64>::new());
}

#[test]
fn break_leaves_a_while_and_nowhere_else() {
    assert_eq!(
        radii("#declare I = 0; #while (1) #if (I = 3) #break #end sphere { 0, 1 } #declare I = I + 1; #end").len(),
        3
    );
    assert!(lower("#break").unwrap_err().contains("outside"));
}

#[test]
fn unmatched_directives_are_named() {
    assert_eq!(lower("#else").unwrap_err(), "`#else` without a matching `#if`");
    assert_eq!(
        lower("#if (1) sphere { 0, 1 }").unwrap_err(),
        "`#if` is not closed by `#end` before the end of the scene file"
    );
    assert_eq!(lower("#while (1) #case (2) #end").unwrap_err(), "`#case` without a matching `#switch`");
    assert!(lower("#if 1 #end").unwrap_err().contains("expected `(` after `#if`"));
}

#[test]
fn union_applies_transforms_and_texture_to_children() {
    let (s, _) = lower(
        "union {\n sphere { 0, 1 }\n sphere { x, 1 pigment { rgb <0, 1, 0> } }\n \
         sphere { y, 1 finish { ambient 1 } }\n pigment { rgb <1, 0, 0> }\n translate z\n}",
    )
    .unwrap();
    assert_eq!(s.objects.len(), 3);
    let t = DMat4::from_translation(DVec3::Z);
    for o in &s.objects {
        assert_eq!(o.transform.matrix(), t);
    }
    let solid = |i: usize| match &s.objects[i].texture.pigment.pattern {
        PigmentPattern::Solid(c) => *c,
        other => panic!("{other:?}"),
    };
    assert_eq!(solid(0), Color::rgb(1.0, 0.0, 0.0));
    // The union's pigment moves with the union's later transform.
    assert_eq!(s.objects[0].texture.pigment.transform.matrix, t);
    assert_eq!(solid(1), Color::rgb(0.0, 1.0, 0.0));
    // A child with only a finish keeps the default (black) pigment, as in POV-Ray.
    assert_eq!(solid(2), Color::BLACK);
}

#[test]
fn nested_and_declared_unions() {
    let (s, _) = lower(
        "#declare U = union { sphere { 0, 1 } union { sphere { 0, 2 } scale 2 } translate x }\n\
         object { U translate y }\nobject { U pigment { rgb 1 } no_shadow }\n\
         merge { sphere { 0, 3 } #if (1) sphere { 0, 4 } #end }",
    )
    .unwrap();
    // The union flattens into its four spheres; the merge is one object over its two.
    assert_eq!(s.objects.len(), 5);
    assert!(matches!(&s.objects[4].shape, crate::desc::ShapeDesc::Csg { children, .. } if children.len() == 2));
    let inner = s.objects[1].transform.matrix();
    assert_eq!(
        inner,
        DMat4::from_translation(DVec3::Y) * DMat4::from_translation(DVec3::X) * DMat4::from_scale(DVec3::splat(2.0))
    );
    assert!(!s.objects[0].no_shadow && s.objects[2].no_shadow && s.objects[3].no_shadow);
    assert_eq!(s.objects[3].texture.pigment.pattern, PigmentPattern::Solid(Color::WHITE));
}

#[test]
fn scene_items_but_lights_inside_union_are_rejected() {
    for csg in ["union", "difference", "intersection"] {
        assert_eq!(
            lower(&format!("{csg} {{ sphere {{ 0, 1 }} camera {{ }} }}")).unwrap_err(),
            "`camera` is not supported inside a CSG object (`union`, `merge`, `intersection`, `difference`, `clipped_by`)"
        );
    }
    assert!(lower("sphere { 0, 1 clipped_by { background { rgb 1 } } }").unwrap_err().starts_with("`background`"));
    // Lights are welcome: they move with the object (POV-Ray's lamps).
    assert_eq!(lower("union { sphere { 0, 1 } light_source { y, 1 } translate x }").unwrap().0.lights.len(), 1);
}

#[test]
fn shadowless_lights_and_no_shadow_objects() {
    let (s, _) = lower(
        "light_source { <1, 2, 3> color rgb 1 shadowless }\nlight_source { 0, rgb 1 }\n\
         sphere { 0, 1 no_shadow }\nsphere { 0, 1 }",
    )
    .unwrap();
    assert!(s.lights[0].shadowless && !s.lights[1].shadowless);
    assert!(s.objects[0].no_shadow && !s.objects[1].no_shadow);
}

#[test]
fn polygon_points_must_be_coplanar() {
    assert_eq!(
        lower("polygon { 4, <0,0,0>, <1,0,0>, <1,1,0>, <0,1,0.1> }").unwrap_err(),
        "polygon points must lie in one plane; point 4 does not"
    );
    // Rounding in computed points is tolerated (relative to the polygon's size).
    assert!(lower("polygon { 4, <0,0,0>, <1e3,0,0>, <1e3,1e3,0>, <0,1e3,1e-6> }").is_ok());
    assert!(lower("polygon { 5, <0,0,0>, <1,0,1>, <1,1,1>, <0,1,0>, <0,0,0> }").is_ok());
}

#[test]
fn messages() {
    let (_, w) = lower("#debug \"ignored\\n\"\n#warning concat(\"w=\", str(1.5, 0, 2))").unwrap();
    assert_eq!(w.len(), 1);
    assert_eq!(w[0].message, "w=1.50");
    assert_eq!(lower("#if (1) #error \"stop\" #end").unwrap_err(), "#error: stop");
}

#[test]
fn debug_text_is_output_in_order_with_warnings() {
    let (_, out) =
        lower_with_output("#debug \"a=\"\n#debug concat(str(2, 0, 0), \"\\n\")\n#warning \"w\"\n#debug \"end\"")
            .unwrap();
    assert_eq!(out.len(), 4, "{out:?}");
    assert_eq!(out[0], Output::Debug("a=".into()));
    assert_eq!(out[1], Output::Debug("2\n".into()));
    assert!(matches!(&out[2], Output::Warning(d) if d.message == "w"), "{:?}", out[2]);
    assert_eq!(out[3], Output::Debug("end".into()));
}

#[test]
fn log_is_base_10_and_min_max_take_any_number_of_arguments() {
    // Each expected value was printed by POV-Ray 3.7 with `#debug str(...)`.
    assert!((value_of("log(100)") - 2.0).abs() < 1e-12);
    assert!((value_of("ln(10)") - std::f64::consts::LN_10).abs() < 1e-6);
    assert_eq!(value_of("min(3, 1, 2)"), 1.0);
    assert_eq!(value_of("max(3, 7, 2, 5)"), 7.0);
    assert_eq!(value_of("min(4, 9)"), 4.0);
    assert_eq!(value_of("select(-1, 10, 20)"), 10.0);
    assert_eq!(value_of("select(0, 10, 20)"), 20.0);
    assert_eq!(value_of("select(0, 10, 20, 30)"), 20.0);
    assert_eq!(value_of("select(2, 10, 20, 30)"), 30.0);
    assert_eq!(value_of("div(-7, 2)"), -3.0);
    assert!((value_of("atan(1)") - std::f64::consts::FRAC_PI_4).abs() < 1e-6);
    assert!((value_of("acosh(2)") - 1.316958).abs() < 1e-6);
    let err = lower("#declare R = max(1);").unwrap_err();
    assert!(err.contains("`max` takes 2 or more argument(s), found 1"), "{err}");
}

#[test]
fn hollow_is_accepted_and_kept_for_media() {
    let (s, _) = lower(
        "sphere { 0, 1 hollow }\nsphere { 0, 1 hollow off }\nsphere { 0, 1 hollow 1 }\nsphere { 0, 1 }\n\
         union { sphere { 0, 1 } sphere { x, 1 } hollow on }\nplane { y, 0 hollow pigment { rgb 1 } }",
    )
    .unwrap();
    let hollow: Vec<bool> = s.objects.iter().map(|o| o.hollow).collect();
    assert_eq!(hollow, [true, false, true, false, true, true, true]);
    // Nothing else about the object changes: hollow only matters to media, which strahl lacks.
    let (a, _) = lower("sphere { 0, 1 pigment { rgb 1 } }").unwrap();
    let (b, _) = lower("sphere { 0, 1 hollow pigment { rgb 1 } }").unwrap();
    assert_eq!(a.objects[0].texture, b.objects[0].texture);
    assert_eq!(a.objects[0].shape, b.objects[0].shape);
}
