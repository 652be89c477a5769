//! POV-Ray 3.7 text for the generated scenes, written as it is produced: `write_generated_to`
//! holds one object at a time (and no mesh2 sheet at all), so ten million spheres or triangles
//! go to a file without the scene or its text in memory.

use std::fmt::{self, Write as _};
use std::io;

use glam::DVec3;

use super::{cloud, header, sheet, Kind, TORUS_TURNS};
use crate::desc::{Color, FinishDesc, ObjectDesc, PigmentPattern, SceneDesc, ShapeDesc, TextureDesc, Transform};

/// `fmt::Write` onto an `io::Write`, keeping the first I/O error (a `fmt::Error` says only
/// that something failed).
pub struct IoText<W: io::Write> {
    pub inner: W,
    pub error: Option<io::Error>,
}

impl<W: io::Write> fmt::Write for IoText<W> {
    fn write_str(&mut self, s: &str) -> fmt::Result {
        self.inner.write_all(s.as_bytes()).map_err(|e| {
            self.error.get_or_insert(e);
            fmt::Error
        })
    }
}

/// `generate(kind, n, w, h)` as POV-Ray 3.7 scene text for any image size: the camera's right
/// vector is written as `right <r>*image_width/image_height`, so `image_width` and
/// `image_height` (strahl's `-W`/`-H`, POV-Ray's `+W`/`+H`) decide the aspect when it is read.
pub fn write_generated(kind: Kind, n: usize) -> Result<String, String> {
    let mut o = String::with_capacity(128 * n + 1024);
    write_generated_to(&mut o, kind, n, false)?;
    Ok(o)
}

/// `write_generated` onto `o`, object by object; `normals` adds a mesh2 sheet's
/// `normal_vectors` (smooth shading), which `generate` leaves out.
pub fn write_generated_to(o: &mut impl fmt::Write, kind: Kind, n: usize, normals: bool) -> Result<(), String> {
    // At 1×1, `right` is the unit-long r itself (r * 1 / 1 is exact).
    let desc = header(kind, n, 1, 1);
    let r = desc.camera.right;
    write_head(o, &desc, &format!("<{}, {}, {}>*image_width/image_height", r.x, r.y, r.z))?;
    for obj in &desc.objects {
        write_object(o, obj)?;
    }
    if kind == Kind::Mesh2 {
        sheet::write(o, n, normals).map_err(|_| "cannot write the mesh2 sheet".to_string())?;
        write_look(o, &sheet::texture())?;
    }
    for obj in cloud(kind, n) {
        write_object(o, &obj)?;
    }
    Ok(())
}

/// Writes `desc` as POV-Ray 3.7 scene text, camera vectors as they are. Only what the
/// generators produce is supported: untransformed spheres, boxes, triangles, capped cylinders and planes with
/// solid or checker pigments; anything else is an error naming what it found.
pub fn write_pov(desc: &SceneDesc) -> Result<String, String> {
    let r = desc.camera.right;
    let mut o = String::with_capacity(128 * desc.objects.len() + 1024);
    write_head(&mut o, desc, &format!("<{}, {}, {}>", r.x, r.y, r.z))?;
    for obj in &desc.objects {
        write_object(&mut o, obj)?;
    }
    Ok(o)
}

/// A generated torus's transform as `rotate … translate <…>` (one of TORUS_TURNS, then a move),
/// or None for any other transform.
fn torus_modifiers(t: &Transform) -> Option<String> {
    let m = t.matrix;
    let linear = glam::DMat3::from_mat4(m).to_cols_array();
    let (turn, _) = TORUS_TURNS.iter().find(|(_, l)| *l == linear)?;
    let p = m.w_axis.truncate();
    Some(format!("{turn}translate <{}, {}, {}>", p.x, p.y, p.z))
}

fn v(p: DVec3) -> String {
    format!("<{}, {}, {}>", p.x, p.y, p.z)
}

fn rgb(c: &Color) -> Result<String, String> {
    if c.filter != 0.0 || c.transmit != 0.0 {
        Err("filter/transmit colours are not supported by write_pov".to_string())
    } else {
        Ok(format!("rgb {}", v(c.rgb)))
    }
}

/// Everything before the objects, with the camera's `right` written as the expression `right`.
fn write_head(o: &mut impl fmt::Write, desc: &SceneDesc, right: &str) -> Result<(), String> {
    let _ = writeln!(o, "// Written by strahl (scene::generate); renders the same in POV-Ray 3.7 and strahl.");
    let _ = writeln!(o, "#version {};", desc.version);
    let g = &desc.global;
    let _ = write!(
        o,
        "global_settings {{ max_trace_level {} ambient_light {}",
        g.max_trace_level,
        rgb(&Color { rgb: g.ambient_light, ..Color::BLACK })?
    );
    if let Some(gamma) = g.assumed_gamma {
        let _ = write!(o, " assumed_gamma {gamma}");
    }
    let _ = writeln!(o, " }}");
    let c = &desc.camera;
    if c.look_at.is_some() || c.angle.is_some() || c.sky != DVec3::Y {
        return Err("write_pov writes cameras as explicit vectors; clear look_at, angle and sky".into());
    }
    let _ = writeln!(
        o,
        "camera {{\n  location {}\n  direction {}\n  right {right}\n  up {}\n}}",
        v(c.location),
        v(c.direction),
        v(c.up)
    );
    let _ = writeln!(o, "background {{ color {} }}", rgb(&desc.background)?);
    for l in &desc.lights {
        let _ =
            writeln!(o, "light_source {{ {} color {} }}", v(l.position), rgb(&Color { rgb: l.color, ..Color::BLACK })?);
    }
    Ok(())
}

/// `mesh2 { vertex_vectors {..} [normal_vectors {..}] face_indices {..}`, up to the texture.
pub fn write_mesh2(
    o: &mut impl fmt::Write,
    vertices: (usize, impl Iterator<Item = DVec3>),
    normals: Option<(usize, impl Iterator<Item = DVec3>)>,
    faces: (usize, impl Iterator<Item = [u32; 3]>),
) -> fmt::Result {
    fn vectors(
        o: &mut impl fmt::Write,
        name: &str,
        (count, items): (usize, impl Iterator<Item = DVec3>),
    ) -> fmt::Result {
        write!(o, "\n  {name} {{ {count}")?;
        for p in items {
            write!(o, ",\n    <{}, {}, {}>", p.x, p.y, p.z)?;
        }
        write!(o, "\n  }}")
    }
    write!(o, "mesh2 {{")?;
    vectors(o, "vertex_vectors", vertices)?;
    if let Some(normals) = normals {
        vectors(o, "normal_vectors", normals)?;
    }
    let (count, faces) = faces;
    write!(o, "\n  face_indices {{ {count}")?;
    for [a, b, c] in faces {
        write!(o, ",\n    <{a}, {b}, {c}>")?;
    }
    write!(o, "\n  }}\n ")
}

/// One object: its shape, then its pigment and finish.
fn write_object(o: &mut impl fmt::Write, obj: &ObjectDesc) -> Result<(), String> {
    // A torus may be turned by one of TORUS_TURNS and moved; nothing else is transformed.
    let placed = match obj.shape {
        ShapeDesc::Torus { .. } => torus_modifiers(&obj.transform.transform()),
        _ => obj.transform.is_identity().then(String::new),
    };
    let Some(placed) = placed.filter(|_| obj.texture.pigment.transform.is_identity()) else {
        return Err(format!("write_pov: transformed {} is not supported", obj.shape.keyword()));
    };
    if obj.texture.normal.is_some() || obj.texture.pigment.turbulence.is_some() || obj.interior.ior != 1.0 {
        return Err(format!("write_pov: {} with normal, turbulence or interior is not supported", obj.shape.keyword()));
    }
    match &obj.shape {
        ShapeDesc::Sphere { center, radius } => {
            let _ = write!(o, "sphere {{ {}, {radius}", v(*center));
        }
        ShapeDesc::Box { corner1, corner2 } => {
            let _ = write!(o, "box {{ {}, {}", v(*corner1), v(*corner2));
        }
        ShapeDesc::Triangle { a, b, c } => {
            let _ = write!(o, "triangle {{ {}, {}, {}", v(*a), v(*b), v(*c));
        }
        ShapeDesc::Plane { normal, distance } => {
            let _ = write!(o, "plane {{ {}, {distance}", v(*normal));
        }
        ShapeDesc::Cone { base, base_radius, cap, cylinder: true, open: false, .. } => {
            let _ = write!(o, "cylinder {{ {}, {}, {base_radius}", v(*base), v(*cap));
        }
        ShapeDesc::Mesh { mesh, inside_vector: None } if mesh.normals.is_empty() => {
            let _ = write_mesh2(
                o,
                (mesh.vertices.len(), mesh.vertices.iter().copied()),
                None::<(usize, std::iter::Empty<DVec3>)>,
                (mesh.faces.len(), mesh.faces.iter().map(|f| f.vertices)),
            );
        }
        ShapeDesc::Torus { major, minor } => {
            let _ = write!(o, "torus {{ {major}, {minor} {placed}");
        }
        other @ (ShapeDesc::Polygon { .. }
        | ShapeDesc::Mesh { .. }
        | ShapeDesc::HeightField { .. }
        | ShapeDesc::Cone { .. }
        | ShapeDesc::Disc { .. }
        | ShapeDesc::Csg { .. }
        | ShapeDesc::Poly { .. }
        | ShapeDesc::Superellipsoid { .. }
        | ShapeDesc::Prism { .. }
        | ShapeDesc::Text { .. }
        | ShapeDesc::Lathe { .. }
        | ShapeDesc::Sor { .. }
        | ShapeDesc::Blob { .. }
        | ShapeDesc::Julia { .. }
        | ShapeDesc::Isosurface { .. }
        | ShapeDesc::Parametric { .. }) => {
            return Err(format!("write_pov: {} is not supported", other.keyword()));
        }
    }
    write_look(o, &obj.texture)
}

/// An object's pigment and finish, and its closing brace.
fn write_look(o: &mut impl fmt::Write, texture: &TextureDesc) -> Result<(), String> {
    match &texture.pigment.pattern {
        PigmentPattern::Solid(c) => {
            let _ = write!(o, " pigment {{ color {} }}", rgb(c)?);
        }
        PigmentPattern::Checker(a, b) => {
            let _ = write!(o, " pigment {{ checker color {} color {} }}", rgb(a)?, rgb(b)?);
        }
        _ => return Err("write_pov: only solid and checker pigments are supported".into()),
    }
    let (f, default_finish) = (&texture.finish, FinishDesc::default());
    let mut items = String::new();
    if f.ambient != default_finish.ambient {
        let _ = write!(items, " ambient {}", rgb(&Color { rgb: f.ambient, ..Color::BLACK })?);
    }
    if f.diffuse != default_finish.diffuse {
        let _ = write!(items, " diffuse {}", f.diffuse);
    }
    if f.phong != default_finish.phong {
        let _ = write!(items, " phong {}", f.phong);
    }
    if f.reflection != default_finish.reflection {
        let _ = write!(items, " reflection {}", rgb(&Color { rgb: f.reflection, ..Color::BLACK })?);
    }
    if f.brilliance != default_finish.brilliance
        || f.phong_size != default_finish.phong_size
        || f.specular != default_finish.specular
        || f.roughness != default_finish.roughness
    {
        return Err("write_pov: brilliance, phong_size, specular and roughness are not supported".into());
    }
    if !items.is_empty() {
        let _ = write!(o, " finish {{{items} }}");
    }
    let _ = writeln!(o, " }}");
    Ok(())
}
