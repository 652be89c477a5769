//! The scene language as POV-Ray runs it: macros, loops, arrays, strings, file I/O, directives
//! inside blocks and expressions, lazy declarations and error chains. Each scene is written to a
//! fresh folder and loaded through the library, as `strahl render` loads it.

use std::path::{Path, PathBuf};

use glam::DVec3;
use strahl::desc::{SceneDesc, ShapeDesc};
use strahl::error::LocatedError;
use strahl::pov::{load_scene_with_messages, IncludePath, Message, ParseOptions};

fn dir(test: &str) -> PathBuf {
    let d = Path::new(env!("CARGO_TARGET_TMPDIR")).join("language").join(test);
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

/// Loads `text` as `scene.pov` in a fresh folder (with `files` beside it): the scene and the
/// `#debug` text it printed.
fn load_with(test: &str, text: &str, files: &[(&str, &str)]) -> Result<(SceneDesc, String), LocatedError> {
    let d = dir(test);
    for (name, body) in files {
        std::fs::write(d.join(name), body).unwrap();
    }
    let path = d.join("scene.pov");
    std::fs::write(&path, text).unwrap();
    let (scene, messages) = load_scene_with_messages(&path, &IncludePath::default(), &ParseOptions::default())?;
    let debug = messages
        .iter()
        .filter_map(|m| match m {
            Message::Debug(t) => Some(t.as_str()),
            Message::Warning(_) => None,
        })
        .collect();
    Ok((scene, debug))
}

fn load(test: &str, text: &str) -> Result<(SceneDesc, String), LocatedError> {
    load_with(test, text, &[])
}

fn debug(test: &str, text: &str) -> String {
    load(test, &format!("{text}\nsphere {{ 0, 1 }}")).unwrap_or_else(|e| panic!("{test}: {e}")).1
}

fn error(test: &str, text: &str) -> LocatedError {
    match load(test, text) {
        Ok(_) => panic!("{test}: the scene loaded"),
        Err(e) => e,
    }
}

fn spheres(scene: &SceneDesc) -> Vec<(DVec3, f64)> {
    scene
        .objects
        .iter()
        .filter_map(|o| match o.shape {
            ShapeDesc::Sphere { center, radius } => Some((center, radius)),
            _ => None,
        })
        .collect()
}

#[test]
fn macros_expand_to_objects_expressions_and_block_items() {
    let (s, _) = load(
        "macro_kinds",
        "#macro Ball(P, R) sphere { P, R } #end\n\
         #macro Sq(X) (X * X) #end\n\
         #macro Red() rgb <1, 0, 0> #end\n\
         Ball(<1, 0, 0>, Sq(3))\n\
         union { Ball(0, 1) Ball(y, 2) pigment { Red() } }\n\
         sphere { 0, 1 + Sq(2) }",
    )
    .unwrap();
    let radii: Vec<f64> = spheres(&s).iter().map(|&(_, r)| r).collect();
    assert_eq!(radii, vec![9.0, 1.0, 2.0, 5.0]);
}

#[test]
fn macro_parameters_by_reference_optional_and_local() {
    let out = debug(
        "macro_params",
        "#macro Inc(V) #declare V = V + 1; #end\n\
         #macro Opt(A, optional B) #ifdef (B) #debug \"with B\\n\" #else #debug \"no B\\n\" #end #end\n\
         #macro Loc() #local T = 5; #debug concat(\"T=\", str(T, 0, 0), \"\\n\") #end\n\
         #declare N = 1; Inc(N) Inc(N)\n\
         #declare M = 1; Inc(M + 0)\n\
         Opt(1) Opt(1, 2) Loc()\n\
         #ifndef (T) #debug \"T gone\\n\" #end\n\
         #debug concat(\"N=\", str(N, 0, 0), \" M=\", str(M, 0, 0), \"\\n\")",
    );
    assert_eq!(out, "no B\nwith B\nT=5\nT gone\nN=3 M=1\n");
}

#[test]
fn recursion_runs_and_runaway_recursion_is_a_located_error() {
    let out = debug(
        "macro_recursion",
        "#macro Fact(K) #if (K <= 1) 1 #else K * Fact(K - 1) #end #end\n\
         #debug concat(str(Fact(6), 0, 0), \"\\n\")",
    );
    assert_eq!(out, "720\n");
    let e = error("macro_runaway", "#macro R(N) R(N + 1) #end\nR(0)");
    assert_eq!((e.line, e.col), (1, 13), "{e}");
    assert!(e.message.starts_with("macro calls nested deeper than"), "{e}");
    assert!(e.message.contains("in macro `R` (defined at "), "{e}");
    assert!(e.message.contains("and 988 more macro calls"), "{e}");
}

#[test]
fn errors_inside_macros_name_the_chain_of_calls_and_includes() {
    let d = "#macro Bad(X) sphere { X, -1 } #end\n#macro Outer() Bad(0) #end\n";
    let e = match load_with("macro_chain", "#include \"lib.inc\"\nOuter()\n", &[("lib.inc", d)]) {
        Ok(_) => panic!("loaded"),
        Err(e) => e,
    };
    assert!(e.file.ends_with("lib.inc"), "{e}");
    assert_eq!((e.line, e.col), (1, 27), "{e}");
    let lines: Vec<&str> = e.message.lines().collect();
    assert_eq!(lines[0], "sphere radius must be positive", "{e}");
    assert!(lines[1].contains("in macro `Bad` (defined at ") && lines[1].ends_with("lib.inc:2:16"), "{e}");
    assert!(lines[2].contains("in macro `Outer`") && lines[2].ends_with("scene.pov:2:1"), "{e}");
}

#[test]
fn loops_for_while_switch_and_break() {
    let out = debug(
        "loops",
        "#for (I, 1, 3) #debug str(I, 0, 0) #end #debug \"|\"\n\
         #for (I, 3, 1, -1) #debug str(I, 0, 0) #end #debug \"|\"\n\
         #for (I, 0, 1, 0.5) #debug str(I, 0, 1) #debug \" \" #end #debug \"|\"\n\
         #declare J = 0; #while (1) #declare J = J + 1; #if (J > 4) #break #end #end #debug str(J, 0, 0) #debug \"|\"\n\
         #for (K, 0, 3) #switch (K) #case (0) #debug \"a\" #case (1) #debug \"b\" #break #range (2, 5) #debug \"c\" #else #debug \"d\" #end #end",
    );
    // The same output as POV-Ray 3.7 (a clause runs on into the next until `#break`).
    assert_eq!(out, "123|321|0.0 0.5 1.0 |5|abbcdcd");
}

#[test]
fn directives_stand_anywhere_a_token_may() {
    let (s, _) = load(
        "directives_inside",
        "#declare Big = 1;\n\
         sphere { <0, #if (Big) 5 #else 1 #end, 0>, #declare R = 2; R }\n\
         union { #for (I, 1, 3) sphere { x * I, 0.5 } #end }\n\
         camera { location <0, 0, -5> #if (Big) look_at 0 #end }",
    )
    .unwrap();
    assert_eq!(spheres(&s)[0], (DVec3::new(0.0, 5.0, 0.0), 2.0));
    assert_eq!(spheres(&s).len(), 4);
    assert_eq!(s.camera.look_at, Some(DVec3::ZERO));
}

#[test]
fn a_declaration_is_stored_before_the_next_directive_reads_it_even_without_semicolons() {
    let out = debug(
        "no_semicolons",
        "#macro Show(V) #debug V #end\n\
         #declare A = 1\n#declare B = A + 1\n#declare S = sphere { 0, B }\n#declare T = object { S }\n\
         #if (B = 2) #debug \"ok\" #end\n#declare C = \" and C\"\nShow(C)",
    );
    assert_eq!(out, "ok and C");
}

#[test]
fn arrays_of_one_to_five_dimensions() {
    let out = debug(
        "arrays",
        "#declare A = array[2][3] { {1, 2, 3}, {4 5 6} }\n\
         #declare B = array[4];\n#declare B[2] = \"x\";\n\
         #declare O = array[2] { sphere { 0, 1 }, sphere { 0, 2 } }\n\
         #debug concat(str(A[1][2], 0, 0), str(dimensions(A), 0, 0), str(dimension_size(A, 2), 0, 0), B[2])\n\
         #ifdef (B[1]) #debug \"set\" #else #debug \"unset\" #end\n\
         #if (defined(B[2])) #debug \"def\" #end",
    );
    assert_eq!(out, "623xunsetdef");
    let e = error("array_range", "#declare A = array[2];\n#declare A[2] = 1;");
    assert_eq!((e.line, e.col), (2, 1), "{e}");
    assert!(e.message.contains("out of range"), "{e}");
    let e = error("array_unset", "#declare A = array[2];\n#declare X = A[0];");
    assert!(e.message.contains("has no value yet"), "{e}");
    let e = error("array_size", "#declare A = array[100000][100000];");
    assert!(e.message.contains("elements in all at most"), "{e}");
}

#[test]
fn string_functions_as_pov_ray_3_7() {
    let out = debug(
        "strings",
        "#declare S = \"Hello\";\n\
         #debug concat(strupr(S), \",\", strlwr(S), \",\", substr(S, 2, 3), \",\", chr(65), \",\")\n\
         #debug concat(str(strlen(S), 0, 0), \",\", str(asc(\"a\"), 0, 0), \",\", str(val(\"12.5x\"), 0, 1), \",\")\n\
         #debug concat(str(strcmp(\"a\", \"b\"), 0, 0), \",\", vstr(3, <1, 2, 3>, \"_\", 0, 1), \",\", str(7, -3, 0))",
    );
    assert_eq!(out, "HELLO,hello,ell,A,5,97,12.5,-1,1.0_2.0_3.0,007");
    let e = error("substr_range", "#declare S = substr(\"abc\", 3, 5);");
    assert!(e.message.contains("outside the string"), "{e}");
}

#[test]
fn rand_is_deterministic_per_seed_and_in_range() {
    let text = "#declare R = seed(42); #declare Q = seed(7);\n\
                #for (I, 1, 50) #declare V = rand(R); #if (V < 0 | V >= 1) #error \"range\" #end #end\n\
                #debug concat(str(rand(R), 0, 9), \" \", str(rand(Q), 0, 9))";
    let a = debug("rand_a", text);
    let b = debug("rand_b", text);
    assert_eq!(a, b);
    let (x, y) = a.split_once(' ').unwrap();
    assert_ne!(x, y, "different seeds give different numbers");
}

/// POV-Ray 3.7's own numbers (`povray` printing `str(rand(S), 0, 17)`), so scenes that scatter
/// objects with `rand` place them where POV-Ray does: seed 0's first six, the first of seeds
/// -7 and 2.7 (truncated), and of 5e9 (out of 32-bit range).
#[test]
#[allow(clippy::excessive_precision)] // POV-Ray's 17 printed digits, as printed
fn rand_gives_pov_rays_sequence() {
    let out = debug(
        "rand_pov",
        "#declare S = seed(0); #declare N = seed(-7); #declare F = seed(2.7); #declare B = seed(5000000000);\n\
         #for (I, 1, 6) #debug concat(str(rand(S), 0, 17), \" \") #end\n\
         #debug concat(str(rand(N), 0, 17), \" \", str(rand(F), 0, 17), \" \", str(rand(B), 0, 17))",
    );
    let got: Vec<f64> = out.split_whitespace().map(|v| v.parse().unwrap()).collect();
    let pov = [
        0.00000287429429658,
        0.46656368450880137,
        0.24907022883395438,
        0.96587604213642797,
        0.63650403303012815,
        0.86381908200304469,
        0.04607286817535592,
        0.84398287624213442,
        0.50000287441071189,
    ];
    assert_eq!(got.len(), pov.len(), "{out}");
    for (g, p) in got.iter().zip(pov) {
        assert!((g - p).abs() < 1e-15, "{g} vs POV-Ray's {p} in {out}");
    }
}

#[test]
fn vector_functions_rotate_as_rotate_does() {
    let out = debug(
        "vectors",
        "#declare V = vrotate(x, <0, 90, 0>); #declare W = vaxis_rotate(x, y, 90);\n\
         #debug concat(vstr(3, V, \",\", 0, 3), \" \", vstr(3, W, \",\", 0, 3))",
    );
    assert_eq!(out, "0.000,0.000,-1.000 0.000,0.000,-1.000");
}

#[test]
fn undef_and_version() {
    let out = debug(
        "undef",
        "#declare A = 1; #undef A #ifndef (A) #debug \"gone\" #end\n\
         #local V = version; #version 3.5; #debug str(version, 0, 1) #version V;",
    );
    assert_eq!(out, "gone3.5");
}

#[test]
fn files_are_written_and_read_back_beside_the_scene() {
    let text = "#fopen F \"data.txt\" write\n#write (F, 1.5, \",\", <1, 2, 3>, \",\\\"s\\\"\")\n#fclose F\n\
                #fopen G \"data.txt\" read\n#read (G, A, B, C)\n#declare N = 0;\n\
                #while (defined(G)) #read (G, D) #declare N = N + 1; #end\n\
                #debug concat(str(A, 0, 1), vstr(3, B, \" \", 0, 0), C, str(N, 0, 0))\nsphere { 0, 1 }";
    let (_, out) = load("fileio", text).unwrap();
    assert_eq!(out, "1.51 2 3s0");
    let written = std::fs::read_to_string(dir_path("fileio").join("data.txt")).unwrap();
    assert_eq!(written, "1.5,<1,2,3>,\"s\"");
    let e = error("fileio_outside", "#fopen F \"../x.txt\" write");
    assert!(e.message.starts_with("#fopen writes only inside the scene's folder"), "{e}");
    let e = error("fileio_missing", "#fopen F \"none.txt\" read");
    assert!(e.message.contains("not found"), "{e}");
}

fn dir_path(test: &str) -> PathBuf {
    Path::new(env!("CARGO_TARGET_TMPDIR")).join("language").join(test)
}

#[test]
fn unmodelled_declarations_fail_only_where_they_are_used() {
    let text =
        "#declare T = texture { pigment { tiling 1 } }\n#declare U = texture { T }\n#declare C = sphere_sweep { linear_spline 2, 0, 1, x, 1 }\n";
    assert!(load("lazy_unused", &format!("{text}sphere {{ 0, 1 }}")).is_ok());
    let e = error("lazy_used", &format!("{text}sphere {{ 0, 1 texture {{ U }} }}"));
    assert_eq!((e.line, e.col), (4, 25), "{e}");
    assert!(e.message.starts_with("this declaration cannot be used: `tiling` is not supported in pigment"), "{e}");
    assert!(e.message.contains("scene.pov:1:34"), "the note points at `tiling`: {e}");
    let e = error("lazy_object", &format!("{text}object {{ C }}"));
    assert!(e.message.contains("`sphere_sweep` is not supported"), "{e}");
    // A misspelt keyword in a declaration is still an error where it is written.
    let e = error("lazy_typo", "#declare T = texture { pigment { rgb 1 } finsh { } }");
    assert!(e.message.starts_with("unknown keyword `finsh`"), "{e}");
}

#[test]
fn unclosed_and_unmatched_blocks_are_located() {
    let e =
        match load_with("open_if_in_include", "#include \"open.inc\"\nsphere { 0, 1 }", &[("open.inc", "#if (1)\n")]) {
            Ok(_) => panic!("loaded"),
            Err(e) => e,
        };
    assert!(e.file.ends_with("open.inc"), "{e}");
    assert!(e.message.starts_with("`#if` is not closed by `#end` before the end of the file"), "{e}");
    let e = error("open_macro", "#macro M() #if (1) sphere { 0, 1 } #end\nM()");
    assert!(e.message.starts_with("`#macro` is not closed by `#end`"), "{e}");
    let e = error("open_while", "#declare I = 0;\n#while (I < 2) #declare I = I + 1;");
    assert_eq!((e.line, e.col), (2, 1), "{e}");
    let e = error("stray_end", "sphere { 0, 1 }\n#end");
    assert_eq!((e.line, e.col), (2, 1), "{e}");
}

#[test]
fn clock_values_come_from_the_parse_options() {
    let d = dir("clock");
    let path = d.join("scene.pov");
    std::fs::write(&path, "sphere { 0, 1 + clock + clock_on }").unwrap();
    let options = ParseOptions { clock: strahl::pov::Clock::frame(0.0, 2.0, 1, 3), ..ParseOptions::default() };
    let (s, _) = load_scene_with_messages(&path, &IncludePath::default(), &options).unwrap();
    assert_eq!(spheres(&s)[0].1, 3.0);
}

#[test]
fn a_runaway_loop_that_prints_stops_at_the_output_limit() {
    let text = format!("#declare S = \"{}\";\n#while (1) #debug S #end", "x".repeat(4096));
    let e = error("print_limit", &text);
    assert_eq!((e.line, e.col), (2, 12), "{e}");
    assert!(e.message.starts_with("the scene printed more than"), "{e}");
}

/// `matrix`, `transform { }` and declared transforms (3.3.1.12.4–5) in objects, with
/// `inverse`, and from a macro that writes the block (transforms.inc's Reorient_Trans does).
#[test]
fn transforms_as_values_and_matrices() {
    let (s, _) = load(
        "transforms",
        "#declare T = transform { scale 2 translate x }\n\
         #macro M() transform { T inverse } #end\n\
         sphere { 0, 1 transform T }\n\
         sphere { 0, 1 transform { T translate y } }\n\
         sphere { 0, 1 M() }\n\
         sphere { 0, 1 matrix <1, 0, 0, 0.5, 1, 0, 0, 0, 1, 0, 0, 3> }",
    )
    .unwrap();
    let at = |i: usize, p: DVec3| s.objects[i].transform.matrix().transform_point3(p);
    assert!((at(0, DVec3::X) - DVec3::new(3.0, 0.0, 0.0)).length() < 1e-12);
    assert!((at(1, DVec3::X) - DVec3::new(3.0, 1.0, 0.0)).length() < 1e-12);
    assert!((at(2, DVec3::new(3.0, 0.0, 0.0)) - DVec3::X).length() < 1e-12);
    // The second row is where y goes: a shear of x by y, then the last row's translation.
    assert!((at(3, DVec3::Y) - DVec3::new(0.5, 1.0, 3.0)).length() < 1e-12);
}

#[test]
fn transform_errors_are_located() {
    let e = error("e_matrix_short", "sphere { 0, 1\n  matrix <1, 0, 0, 0, 1, 0> }");
    assert_eq!((e.line, e.col), (2, 27), "{e}");
    assert!(e.message.contains("between the 12 values of `matrix`"), "{e}");
    let e = error("e_matrix_flat", "sphere { 0, 1\n  matrix <1,0,0, 0,0,0, 0,0,1, 0,0,0> }");
    assert_eq!(
        (e.line, e.col, e.message.as_str()),
        (2, 3, "`matrix` is singular (it flattens space), so it has no inverse")
    );
    let e = error("e_transform_kind", "#declare P = pigment { rgb 1 }\nsphere { 0, 1 transform { P } }");
    assert_eq!((e.line, e.col), (2, 27), "{e}");
    assert_eq!(e.message, "expected a transform in `transform { }`, found a pigment");
}

/// `min_extent`, `max_extent`, `trace` (with its normal variable) and `inside` on a declared
/// union, with the values POV-Ray 3.7 prints for the same scene (`#debug`).
#[test]
fn object_probes_match_povray() {
    let out = debug(
        "probes",
        "#declare S = union { sphere { <1, 2, 3>, 1 } box { <-1, -1, -1>, <0, 0.5, 0> } }\n\
         #debug concat(vstr(3, min_extent(S), \",\", 0, 4), \" \", vstr(3, max_extent(S), \",\", 0, 4), \"\\n\")\n\
         #declare N = <9, 9, 9>;\n\
         #declare P = trace(S, <1, 2, -10>, z, N);\n\
         #debug concat(vstr(3, P, \",\", 0, 4), \" \", vstr(3, N, \",\", 0, 4), \"\\n\")\n\
         #declare P = trace(S, <10, 20, -10>, z, N);\n\
         #debug concat(vstr(3, P, \",\", 0, 4), \" \", vstr(3, N, \",\", 0, 4), \"\\n\")\n\
         #declare P = trace(S, <1, 2, 3>, z, N);\n\
         #debug concat(vstr(3, P, \",\", 0, 4), \" \", vstr(3, N, \",\", 0, 4), \"\\n\")\n\
         #debug concat(str(inside(S, <1,2,3.5>), 0, 0), str(inside(S, <-0.5,0,-0.5>), 0, 0), str(inside(S, <5,5,5>), 0, 0))",
    );
    assert_eq!(
        out,
        "-1.0000,-1.0000,-1.0000 2.0000,3.0000,4.0000\n\
         1.0000,2.0000,2.0000 0.0000,0.0000,-1.0000\n\
         0.0000,0.0000,0.0000 0.0000,0.0000,0.0000\n\
         1.0000,2.0000,4.0000 0.0000,0.0000,1.0000\n\
         110"
    );
    let e = error("e_probe", "#declare P = pigment { rgb 1 }\n#declare A = max_extent(P);");
    assert_eq!((e.line, e.col, e.message.as_str()), (2, 25, "`max_extent` needs a declared object, found a pigment"));
    let e = error("e_trace_n", "#declare S = sphere { 0, 1 }\n#declare A = trace(S, -5*z, z, Nope);");
    assert_eq!((e.line, e.col), (2, 32), "{e}");
}

/// Pattern and pigment functions (`function { pattern {..} }`, `function { pigment {..} }`)
/// with the values POV-Ray 3.7 prints for the same calls (`#debug`): a pigment function's
/// call is a colour, `.gray` is 0.297 r + 0.589 g + 0.114 b, a body reads one channel, a
/// pattern function gives the pattern's value (checker 0/1, gradient wrapped, wood's wave).
#[test]
fn pattern_and_pigment_functions_match_povray() {
    let out = debug(
        "shade_functions",
        "#declare P = function { pigment { color rgbft <0.2, 0.5, 0.9, 0.3, 0.1> } }\n\
         #debug concat(vstr(5, P(1, 2, 3), \",\", 0, 4), \" \", str(P(0, 0, 0).gray, 0, 4), \" \", str(P(0, 0, 0).t, 0, 4), \"\\n\")\n\
         #declare G = function { P(x, y, z).gray * 2 }\n\
         #debug concat(str(G(0, 0, 0), 0, 4), \"\\n\")\n\
         #declare K = function { pattern { checker } }\n\
         #declare Gx = function { pattern { gradient x scale 2 } }\n\
         #declare W = function { pattern { wood } }\n\
         #debug concat(str(K(0.5, 0.5, 0.5), 0, 1), str(K(1.5, 0.5, 0.5), 0, 1), \" \", str(Gx(0.5, 0, 0), 0, 4), \" \", str(Gx(-0.5, 0, 0), 0, 4), \" \", str(W(0.3, 0.4, 0), 0, 4), \"\\n\")\n\
         #declare Pm = function { pigment { gradient x color_map { [0 rgb 0] [1 rgb <1, 0.5, 0>] } } }\n\
         #debug concat(vstr(3, Pm(0.5, 0, 0), \",\", 0, 4), \" \", vstr(2, u + 2 * v, \",\", 0, 1), \"\\n\")",
    );
    assert_eq!(
        out,
        "0.2000,0.5000,0.9000,0.3000,0.1000 0.4565 0.3000\n\
         0.9130\n\
         0.01.0 0.2500 0.7500 1.0000\n\
         0.5000,0.2500,0.0000 1.0,2.0\n"
    );
    let e = error(
        "e_shade_channel",
        "#declare P = function { pigment { rgb 1 } }\n#declare F = function { P(x, y, z) + 1 }",
    );
    assert_eq!((e.line, e.col), (2, 25), "{e}");
    assert!(e.message.contains("is a pigment function"), "{e}");
    let e =
        error("e_shade_member", "#declare P = function { pigment { rgb 1 } }\n#declare F = function { P(x, y, z).w }");
    assert_eq!((e.line, e.col), (2, 36), "{e}");
}

/// `height_field { function W, H { F } }`: F sampled at x = i / (W − 1), y = j / (H − 1) with
/// row 0 at the field's far edge (z = 1), values beyond [0, 1] wrapped (POV-Ray 3.7's `trace`
/// on 3×3 fields: 0.1 + 0.5x + 0.3y is 0.4 at the near left corner; 2x − 0.5 is 0.5 everywhere).
#[test]
fn height_field_functions_sample_the_unit_square() {
    let (scene, _) = load(
        "hf_function",
        "height_field { function 3, 3 { 0.1 + 0.5 * x + 0.3 * y } smooth }\n\
         height_field { function 3, 3 { 2 * x - 0.5 } }\n\
         height_field { function 2, 2 { pigment { rgb <1, 0.5, 0> } } }",
    )
    .unwrap();
    let fields: Vec<_> = scene
        .objects
        .iter()
        .filter_map(|o| match &o.shape {
            ShapeDesc::HeightField { field, smooth, .. } => Some((field.clone(), *smooth)),
            _ => None,
        })
        .collect();
    assert_eq!(fields.len(), 3);
    let (f, smooth) = &fields[0];
    assert!(*smooth);
    assert_eq!((f.width, f.height), (3, 3));
    let near = |a: f32, b: f32| (a - b).abs() < 1e-4;
    assert!(near(f.heights[0], 0.1) && near(f.heights[2], 0.6) && near(f.heights[6], 0.4), "{:?}", f.heights);
    assert!(fields[1].0.heights.iter().all(|&h| near(h, 0.5)), "{:?}", fields[1].0.heights);
    assert!(near(fields[2].0.heights[0], 0.5915), "{:?}", fields[2].0.heights);
    let e = error("e_hf_size", "height_field { function 1, 3 { x } }");
    assert_eq!((e.line, e.col), (1, 16), "{e}");
}

// ---- The sample scenes' language errors (objects/primitiv.pov, advanced/desk/desk.pov,
// interior/media/media2.pov, language/trace.pov, language/tracevines.pov, incdemo/screen.pov,
// gamma/gamma_showcase.pov, advanced/abyss.pov, animations/splinefollow/splinefollow.pov,
// camera/mesh_camera/meshcam_persp_demo.pov): each checked against `povray` 3.7.

fn close(a: DVec3, b: DVec3) -> bool {
    (a - b).length() < 1e-9
}

#[test]
fn poly_coefficients_may_leave_out_commas_as_in_a_vector() {
    // primitiv.pov's quartic: `0    1.5,` (POV-Ray reads `<1 2 3>` as `<1, 2, 3>` too).
    let (s, _) = load(
        "poly_commas",
        "quartic { <1, 0, 0, 0, 2, 0, 0, 2, 0, -2.5, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,\n\
         1, 0, 0, 2, 0    1.5,     0, 0, 0,  0, 1, 0,    -2.5,       0, 0.5625> }",
    )
    .unwrap();
    assert_eq!(s.objects.len(), 1);
    let e = error("poly_commas_count", "quartic { <1 2 3> }");
    assert!(e.to_string().contains("quartic takes 35 coefficients, found 3"), "{e}");
}

#[test]
fn a_declared_light_placed_as_an_object_moves_with_its_transforms_and_looks_like() {
    // desk.pov's `object { Lamp_Light_Source }` and media2.pov's `object { Spot rotate .. }`.
    let (s, _) = load(
        "light_object",
        "#declare L = light_source { <1, 0, 0> color rgb 1 spotlight point_at <2, 0, 0>\n\
           looks_like { sphere { 0, 0.5 } } }\n\
         object { L rotate 90*z }\n\
         union { object { L translate 5*y } }\n\
         light_source { L translate z }",
    )
    .unwrap();
    let at: Vec<(DVec3, DVec3)> = s.lights.iter().map(|l| (l.position, l.point_at)).collect();
    assert_eq!(s.lights.len(), 3, "{at:?}");
    assert!(close(at[0].0, DVec3::new(0.0, 1.0, 0.0)) && close(at[0].1, DVec3::new(0.0, 2.0, 0.0)), "{at:?}");
    assert!(close(at[1].0, DVec3::new(1.0, 5.0, 0.0)) && close(at[1].1, DVec3::new(2.0, 5.0, 0.0)), "{at:?}");
    assert!(close(at[2].0, DVec3::new(1.0, 0.0, 1.0)), "{at:?}");
    // Each placement brings the looks_like sphere, centred on its light and casting no shadow.
    assert_eq!(s.objects.len(), 3);
    for (o, (p, _)) in s.objects.iter().zip(&at) {
        assert!(close(o.transform.matrix().transform_point3(DVec3::ZERO), *p), "{:?} vs {p}", o.transform);
        assert!(o.no_shadow);
    }
}

#[test]
fn a_local_takes_the_value_of_a_macro_that_ends_after_it() {
    // tracevines.pov: `#local NewTmp = FindTmp(..)` where FindTmp ends in `#if (..) Q; #end`.
    let out = debug(
        "local_from_macro",
        "#macro F(A) #local Q = A * 2; #if (1) Q; #else 0; #end #end\n\
         #macro G() #local N = F(3) #debug str(N, 0, 1) #end\n\
         G()",
    );
    assert_eq!(out, "6.0");
}

#[test]
fn a_macro_call_after_a_declared_texture_runs_once_the_texture_is_stored() {
    // incdemo/screen.pov: `#declare T = texture { .. }` then `Screen_Plane(T, ..)`.
    let (s, _) = load(
        "macro_after_texture",
        "#macro P(Texture) box { 0, 1 texture { Texture } } #end\n\
         #declare T0 = texture { pigment { rgb <1, 0, 0> } }\n\
         P(T0)",
    )
    .unwrap();
    assert_eq!(s.objects.len(), 1);
}

#[test]
fn reflection_min_and_max_may_leave_out_the_comma() {
    // gamma_showcase.pov: `reflection { 0.0 1.0 fresnel on }`.
    let (s, _) = load("reflection_pair", "sphere { 0, 1 finish { reflection { 0.1 0.75 fresnel on } } }").unwrap();
    let f = &s.objects[0].texture.finish;
    assert_eq!(f.reflection_min, Some(DVec3::splat(0.1)));
    assert_eq!(f.reflection, DVec3::splat(0.75));
    let e = error("reflection_pair_bad", "sphere { 0, 1 finish { reflection { 0.1 0.75 0.5 } } }");
    assert!(e.to_string().contains("reflection"), "{e}");
}

#[test]
fn global_lights_may_follow_a_light_groups_modifiers() {
    // abyss.pov: `light_group { object { .. } light_source { .. } translate .. global_lights on }`.
    let (s, _) = load(
        "global_lights_late",
        "light_group { sphere { 0, 1 } light_source { <0, 5, 0> rgb 1 } translate x global_lights on }",
    )
    .unwrap();
    assert_eq!(s.light_groups.len(), 1);
    assert!(s.light_groups[0].global_lights);
}

#[test]
fn trace_and_inside_look_into_csg_objects() {
    // trace.pov traces a difference; biscuit.pov asks `inside` of a merge (logo.inc).
    let out = debug(
        "trace_csg",
        "#declare G = difference {\n\
           union { box { <-1.5, -0.6, -0.001>, <1.5, 0, 0.1> } cylinder { <-1, 0, -0.003>, <-1, 0, 0.11>, 0.5 } }\n\
           cylinder { <0, 0, -0.003>, <0, 0, 0.11>, 0.5 } }\n\
         #declare N = <0, 0, 0>;\n\
         #declare P = trace(G, <-1.499, 2, 0>, <0, -1, 0>, N);\n\
         #debug concat(vstr(3, P, \",\", 0, 4), \" \", str(vlength(N), 0, 3))\n\
         #declare M = merge { sphere { 0, 1 } difference { box { -1, 1 } sphere { 0, 0.5 } translate 3*x } }\n\
         #debug concat(\" \", str(inside(M, <3.8, 0, 0>), 0, 0), str(inside(M, <3, 0, 0>), 0, 0))",
    );
    // povray 3.7: -1.4990,0.0316,0.0000 and a unit normal; inside 1 then 0.
    assert_eq!(out, "-1.4990,0.0316,0.0000 1.000 10");
}

#[test]
fn splines_interpolate_as_pov_ray_3_7() {
    // Figures printed by povray 3.7 for the same splines (uneven keys; cubic holds its second
    // and next-to-last points outside them; a later point with the same key replaces one; the
    // commas between key and point may be left out).
    let out = debug(
        "splines",
        "#declare S = spline { cubic_spline 0, <0, 0>, 1, <1, 2>, 2.5, <3, 1>, 3, <4, 4>, 5, <6, 3> }\n\
         #declare Q = spline { S quadratic_spline }\n\
         #declare F = function { spline { S natural_spline } }\n\
         #declare W = spline { 1, 2*x 0 x 1, 3*x }\n\
         #debug concat(vstr(2, S(1.25), \",\", 0, 5), \" \", vstr(2, S(-1), \",\", 0, 5), \" \")\n\
         #debug concat(vstr(2, Q(2.75), \",\", 0, 5), \" \", vstr(2, F(0.25), \",\", 0, 5), \" \")\n\
         #debug concat(vstr(2, S(1.5, linear_spline), \",\", 0, 5), \" \", vstr(3, W(0.5), \",\", 0, 1), \" \")\n\
         #declare V = S(2).x + S(2).y;\n\
         #debug str(V, 0, 5)",
    );
    assert_eq!(
        out,
        "1.29282,1.94907 1.00000,2.00000 3.47917,2.29167 0.24777,0.78806 1.66667,1.66667 2.0,0.0,0.0 2.98148"
    );
}

#[test]
fn spline_mistakes_are_located_errors() {
    let e = error("spline_no_point", "#declare S = spline { 0, <1, 2> 1 }\nsphere { 0, 1 }");
    assert!(e.to_string().contains("scene.pov:1:"), "{e}");
    let e = error("spline_kind", "#declare S = spline { 0, <1, 2> 1, <2, 3> }\nsphere { S(0.5, bezier_spline), 1 }");
    assert!(e.to_string().contains("expected a spline kind"), "{e}");
    let e = error("spline_float", "#declare S = spline { 0, 1 }\nsphere { 0, 1 }");
    assert!(e.to_string().contains("spline point"), "{e}");
}

#[test]
fn a_transform_function_gives_the_moved_point() {
    // transforms.inc's vtransform, which meshcam_persp_demo.pov calls.
    let out = debug(
        "transform_function",
        "#macro vtransform(vec, trans)\n\
           #local fn = function { transform { trans } }\n\
           #local result = (fn(vec.x, vec.y, vec.z));\n\
           result\n\
         #end\n\
         #declare P = vtransform(<1, 2, 3>, transform { scale 2 translate x });\n\
         #debug vstr(3, P, \",\", 0, 1)",
    );
    assert_eq!(out, "3.0,4.0,6.0");
    let e = error("transform_function_arity", "#declare F = function { transform { scale 2 } }\nsphere { F(1, 2), 1 }");
    assert!(e.to_string().contains("takes 3 arguments"), "{e}");
}

/// A macro whose value ends inside a running `#if` branch (`arrays.inc`'s `Rand_Array_Item`:
/// `#if (..) Array[i] #else #error .. #end`) can be continued by operators after the call, in
/// a declaration and as a pigment's colour (advanced/isocacti.pov); a `#while` after a
/// declaration still waits for the value to be stored.
#[test]
fn a_macro_value_ending_in_an_if_branch_continues_the_expression() {
    let pick = "#declare A = array[2] {rgb 1, rgb <0.5, 1, 0>}\n\
                #macro Pick(Arr)\n  #if (dimensions(Arr) = 1)\n    Arr[1]\n  #else\n    #error \"1D only\"\n  #end\n#end\n";
    let out =
        debug("macro_if_value", &format!("{pick}#declare V = Pick(A)*0.5 + 0.25;\n#debug vstr(5, V, \",\", 0, 3)"));
    assert_eq!(out, "0.500,0.750,0.250,0.250,0.250");
    let (scene, _) = load("macro_if_pigment", &format!("{pick}sphere {{ 0, 1 pigment {{ Pick(A)*0.5 }} }}")).unwrap();
    assert_eq!(scene.objects.len(), 1);
    let out = debug(
        "while_after_if",
        "#declare I = 0;\n#if (1) #declare N = 2 #end\n#while (I < N) #declare I = I + 1 #end\n#debug str(I, 0, 0)",
    );
    assert_eq!(out, "2");
}

/// A function body may read a declared spline per point (`S(t).y`, language/splinefunction.pov),
/// with the spline's own kind or one given; a point used whole is a located error.
#[test]
fn functions_read_declared_splines_per_point() {
    let spline = "#declare S = function { spline { linear_spline 0, <0, 0, 0> 1, <2, 4, 1> 2, <2, 0, 3> } }\n";
    let out = debug(
        "spline_function",
        &format!(
            "{spline}#declare F = function {{ S(x).y + S(x, linear_spline).z }}\n\
             #debug concat(str(F(0.5, 0, 0), 0, 3), \" \", str(F(1.5, 0, 0), 0, 3), \" \", str(S(0.25).x, 0, 3))"
        ),
    );
    assert_eq!(out, "2.500 4.000 0.500");
    let e = error("spline_function_whole", &format!("{spline}#declare F = function {{ S(x) + 1 }}"));
    assert_eq!((e.line, e.col), (2, 25), "{e}");
    assert!(e.message.contains("pick a component"), "{e}");
}
