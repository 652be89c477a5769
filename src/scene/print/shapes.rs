//! Objects: each shape's own syntax, then its texture, interior and transform.

use std::fmt::Write;

use super::texture_blocks::{texture_blocks, Declarations};
use super::transform::modifiers;
use super::{num, vec, vec2s};
use crate::desc::{BlobShape, ComplexFn, Container, CsgOp, JuliaFunction, ObjectDesc, PolyForm, ShapeDesc};

/// An object with its textures and interior; layered textures that its patterns of textures
/// hold go to `d`, to be declared before it.
pub(super) fn object(s: &mut String, o: &ObjectDesc, d: &mut Declarations) {
    write_object(s, o, Some(d));
}

/// An object's shape, CSG and transform alone, for the `object` pattern, which asks only
/// what is inside.
pub(super) fn solid(s: &mut String, o: &ObjectDesc) {
    write_object(s, o, None);
}

fn write_object(s: &mut String, o: &ObjectDesc, mut d: Option<&mut Declarations>) {
    let inverse = if o.inverse { "  inverse\n" } else { "" };
    if let ShapeDesc::Csg { op, children } = &o.shape {
        // The node's transforms and textures are on its shapes.
        match (op, children.split_first()) {
            (CsgOp::Clip, Some((first, clips))) => {
                let _ = writeln!(s, "object {{");
                write_object(s, first, d.as_deref_mut());
                let _ = writeln!(s, "clipped_by {{");
                clips.iter().for_each(|c| write_object(s, c, d.as_deref_mut()));
                let _ = writeln!(s, "}}\n{inverse}}}");
            }
            _ => {
                let _ = writeln!(s, "{} {{", op.keyword());
                children.iter().for_each(|c| write_object(s, c, d.as_deref_mut()));
                let _ = writeln!(s, "{inverse}}}");
            }
        }
        return;
    }
    let _ = match &o.shape {
        ShapeDesc::Sphere { center, radius } => write!(s, "sphere {{ {}, {}", vec(*center), num(*radius)),
        ShapeDesc::Plane { normal, distance } => write!(s, "plane {{ {}, {}", vec(*normal), num(*distance)),
        ShapeDesc::Box { corner1, corner2 } => write!(s, "box {{ {}, {}", vec(*corner1), vec(*corner2)),
        ShapeDesc::Triangle { a, b, c } => write!(s, "triangle {{ {}, {}, {}", vec(*a), vec(*b), vec(*c)),
        ShapeDesc::Polygon { points } => {
            let pts: Vec<String> = points.iter().map(|p| vec(*p)).collect();
            write!(s, "polygon {{ {}, {}", points.len(), pts.join(", "))
        }
        ShapeDesc::Cone { base, base_radius, cap, cap_radius, open, cylinder } => {
            let open = if *open { " open" } else { "" };
            if *cylinder {
                write!(s, "cylinder {{ {}, {}, {}{open}", vec(*base), vec(*cap), num(*base_radius))
            } else {
                let (b, r0, c, r1) = (vec(*base), num(*base_radius), vec(*cap), num(*cap_radius));
                write!(s, "cone {{ {b}, {r0}, {c}, {r1}{open}")
            }
        }
        ShapeDesc::Disc { center, normal, radius, hole } => {
            write!(s, "disc {{ {}, {}, {}, {}", vec(*center), vec(*normal), num(*radius), num(*hole))
        }
        ShapeDesc::Torus { major, minor } => write!(s, "torus {{ {}, {}", num(*major), num(*minor)),
        ShapeDesc::Csg { .. } => unreachable!("written above"),
        ShapeDesc::Superellipsoid { e, n } => write!(s, "superellipsoid {{ <{}, {}>", num(*e), num(*n)),
        ShapeDesc::Poly { order, coefficients, sturm, written } => {
            let c = coefficients;
            let sturm = if *sturm { " sturm" } else { "" };
            let list = |c: &[f64]| c.iter().map(|&k| num(k)).collect::<Vec<_>>().join(", ");
            match written {
                // Back from the order-2 poly x², xy, xz, x, y², yz, y, z², z, 1.
                PolyForm::Quadric => write!(
                    s,
                    "quadric {{ <{}, {}, {}>, <{}, {}, {}>, <{}, {}, {}>, {}",
                    num(c[0]),
                    num(c[4]),
                    num(c[7]),
                    num(c[1]),
                    num(c[2]),
                    num(c[5]),
                    num(c[3]),
                    num(c[6]),
                    num(c[8]),
                    num(c[9])
                ),
                PolyForm::Poly => write!(s, "poly {{ {order}, <{}>{sturm}", list(c)),
                other => write!(s, "{} {{ <{}>{sturm}", other.keyword(), list(c)),
            }
        }
        ShapeDesc::Prism { spline, conic, h1, h2, points, open } => {
            let sweep = if *conic { "conic_sweep" } else { "linear_sweep" };
            let open = if *open { " open" } else { "" };
            let (kw, a, b) = (spline.keyword(), num(*h1), num(*h2));
            write!(s, "prism {{ {kw} {sweep} {a}, {b}, {}, {}{open}", points.len(), vec2s(points))
        }
        ShapeDesc::Lathe { spline, points } => {
            write!(s, "lathe {{ {} {}, {}", spline.keyword(), points.len(), vec2s(points))
        }
        ShapeDesc::Sor { points, open } => {
            let open = if *open { " open" } else { "" };
            write!(s, "sor {{ {}, {}{open}", points.len(), vec2s(points))
        }
        ShapeDesc::Julia { param, function, max_iteration, precision, slice } => {
            let v4 = |v: glam::DVec4| format!("<{}, {}, {}, {}>", num(v.x), num(v.y), num(v.z), num(v.w));
            let f = match function {
                JuliaFunction::QuaternionSqr => "quaternion sqr".to_string(),
                JuliaFunction::QuaternionCube => "quaternion cube".to_string(),
                JuliaFunction::Hypercomplex(ComplexFn::Pwr(x, y)) => {
                    format!("hypercomplex pwr({}, {})", num(*x), num(*y))
                }
                JuliaFunction::Hypercomplex(g) => format!("hypercomplex {}", g.keyword().unwrap_or("sqr")),
            };
            write!(
                s,
                "julia_fractal {{ {} {f} max_iteration {max_iteration} precision {} slice {}, {}",
                v4(**param),
                num(*precision),
                v4(slice.0),
                num(slice.1)
            )
        }
        ShapeDesc::Blob { components, threshold } => {
            let _ = write!(s, "blob {{ threshold {}", num(*threshold));
            for c in components {
                let (r, k) = (num(c.radius), num(c.strength));
                let _ = match c.shape {
                    BlobShape::Sphere { center } => write!(s, "\n  sphere {{ {}, {r}, strength {k}", vec(center)),
                    BlobShape::Cylinder { base, cap } => {
                        write!(s, "\n  cylinder {{ {}, {}, {r}, strength {k}", vec(base), vec(cap))
                    }
                };
                let _ = write!(s, "{} }}", modifiers(&c.transform.matrix));
            }
            Ok(())
        }
        ShapeDesc::Mesh { mesh, inside_vector } => {
            mesh_body(s, mesh);
            match inside_vector {
                Some(v) => write!(s, " inside_vector {}", vec(*v)),
                None => Ok(()),
            }
        }
        ShapeDesc::HeightField { field, smooth, water_level } => {
            let quote = |t: &str| t.replace('\\', "\\\\").replace('"', "\\\"");
            let smooth = if *smooth { " smooth" } else { "" };
            let (format, file, water) = (&field.format, quote(&field.file), num(*water_level));
            write!(s, "height_field {{ {format} \"{file}\"{smooth} water_level {water}")
        }
        ShapeDesc::Isosurface { function, container, params } => {
            let c = match container {
                Container::Box { min, max } => format!("box {{ {}, {} }}", vec(*min), vec(*max)),
                Container::Sphere { center, radius } => format!("sphere {{ {}, {} }}", vec(*center), num(*radius)),
            };
            let open = if params.open { " open" } else { "" };
            write!(
                s,
                "isosurface {{ function {{ /* {} instructions */ }} contained_by {{ {c} }} threshold {} accuracy {} \
                 max_gradient {}{open}",
                function.len(),
                num(params.threshold),
                num(params.accuracy),
                num(params.max_gradient)
            )
        }
        ShapeDesc::Parametric { functions, container, params } => {
            let c = match container {
                Container::Box { min, max } => format!("box {{ {}, {} }}", vec(*min), vec(*max)),
                Container::Sphere { center, radius } => format!("sphere {{ {}, {} }}", vec(*center), num(*radius)),
            };
            let lens = functions.iter().map(|f| format!("function {{ /* {} instructions */ }}", f.len()));
            write!(
                s,
                "parametric {{ {} <{}, {}>, <{}, {}> contained_by {{ {c} }} accuracy {} max_gradient {}",
                lens.collect::<Vec<_>>().join(" "),
                num(params.lo.x),
                num(params.lo.y),
                num(params.hi.x),
                num(params.hi.y),
                num(params.accuracy),
                num(params.max_gradient)
            )
        }
        ShapeDesc::Text { font, string, thickness, offset, .. } => {
            let quote = |t: &str| t.replace('\\', "\\\\").replace('"', "\\\"");
            write!(s, "text {{ ttf \"{}\" \"{}\" {}, {}", quote(font), quote(string), num(*thickness), vec(**offset))
        }
    };
    if let Some(src) = (!o.source.file.is_empty()).then_some(&o.source) {
        let _ = write!(s, " // {}:{}:{}", src.file.replace(['\n', '\r'], " "), src.line, src.col);
    }
    if let Some(d) = d {
        texture_blocks(s, &o.texture, &o.transform.inverse(), d);
        let _ = write!(s, "\n  interior {{ ior {}", num(o.interior.ior));
        if let Some(f) = &o.interior.fade {
            let (distance, power, color) = (num(f.distance), num(f.power), vec(f.color));
            let _ = write!(s, " fade_distance {distance} fade_power {power} fade_color {color}");
        }
        let _ = write!(s, " }}");
    }
    let _ = writeln!(s);
    let _ = writeln!(s, "  {}\n{inverse}}}", modifiers(&o.transform.matrix()).trim_start());
}

/// A mesh as `mesh2` when its faces are all flat or all smooth (its indices as they are), else
/// as `mesh` triangles (each with its own vertices, as `mesh` reads them).
fn mesh_body(s: &mut String, mesh: &crate::desc::MeshDesc) {
    let smooth = mesh.faces.iter().filter(|f| f.normals.is_some()).count();
    let list = |s: &mut String, name: &str, items: &mut dyn Iterator<Item = String>, n: usize| {
        let _ = write!(s, "\n  {name} {{ {n}");
        for it in items {
            let _ = write!(s, ", {it}");
        }
        let _ = write!(s, " }}");
    };
    let ix = |i: [u32; 3]| format!("<{}, {}, {}>", i[0], i[1], i[2]);
    // `uv_vectors` (for `uv_mapping`): one uv triple per face, as the loader keeps them.
    let uv = !mesh.uv_faces.is_empty() && mesh.uv_faces.len() == mesh.faces.len();
    if smooth == 0 || smooth == mesh.faces.len() {
        let _ = write!(s, "mesh2 {{");
        list(s, "vertex_vectors", &mut mesh.vertices.iter().map(|v| vec(*v)), mesh.vertices.len());
        if smooth > 0 {
            list(s, "normal_vectors", &mut mesh.normals.iter().map(|v| vec(*v)), mesh.normals.len());
        }
        if uv {
            list(s, "uv_vectors", &mut mesh.uvs.iter().map(|p| vec2s(&[*p])), mesh.uvs.len());
        }
        list(s, "face_indices", &mut mesh.faces.iter().map(|f| ix(f.vertices)), mesh.faces.len());
        if smooth > 0 {
            let normals = &mut mesh.faces.iter().filter_map(|f| f.normals.map(ix));
            list(s, "normal_indices", normals, mesh.faces.len());
        }
        if uv {
            list(s, "uv_indices", &mut mesh.uv_faces.iter().map(|f| ix(*f)), mesh.uv_faces.len());
        }
        return;
    }
    let _ = write!(s, "mesh {{");
    for (i, f) in mesh.faces.iter().enumerate() {
        let v = |k: usize| vec(mesh.vertices[f.vertices[k] as usize]);
        let _ = match f.normals {
            Some(n) => {
                let n = |k: usize| vec(mesh.normals[n[k] as usize]);
                write!(s, "\n  smooth_triangle {{ {}, {}, {}, {}, {}, {}", v(0), n(0), v(1), n(1), v(2), n(2))
            }
            None => write!(s, "\n  triangle {{ {}, {}, {}", v(0), v(1), v(2)),
        };
        if uv {
            let corners = mesh.uv_faces[i].map(|k| mesh.uvs[k as usize]);
            let _ = write!(s, " uv_vectors {}", vec2s(&corners));
        }
        let _ = write!(s, " }}");
    }
}
