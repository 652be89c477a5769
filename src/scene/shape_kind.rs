//! The kinds of shape a built scene stores, each with a fixed number (statistics are counted
//! per kind, and `Scene` keeps one array per kind).

/// The kinds of shape, in the order the statistics report them.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[repr(u8)]
pub enum ShapeKind {
    Sphere = 0,
    Box = 1,
    Triangle = 2,
    Polygon = 3,
    Plane = 4,
    /// A sphere under non-uniform scale; reported as a sphere.
    Ellipsoid = 5,
    /// `cone` and `cylinder`.
    Cone = 6,
    Disc = 7,
    Torus = 8,
    /// `quadric`, `cubic`, `quartic` and `poly`.
    Poly = 9,
    Superellipsoid = 10,
    /// A CSG node (`intersection`, `difference`, `merge`, `clipped_by`) over leaf primitives.
    Csg = 11,
    /// `prism` (and each glyph of `text`).
    Prism = 12,
    Lathe = 13,
    Sor = 14,
    Blob = 15,
    Julia = 20,
    /// `mesh` and `mesh2`.
    Mesh = 16,
    HeightField = 17,
    Isosurface = 18,
    Parametric = 19,
    /// A `smooth_triangle` outside a mesh; reported as a triangle (as POV-Ray does).
    SmoothTriangle = 21,
}

impl ShapeKind {
    /// In the order the statistics list them (alphabetical, as POV-Ray's).
    pub const ALL: [ShapeKind; 20] = [
        ShapeKind::Blob,
        ShapeKind::Box,
        ShapeKind::Cone,
        ShapeKind::Csg,
        ShapeKind::Disc,
        ShapeKind::HeightField,
        ShapeKind::Isosurface,
        ShapeKind::Julia,
        ShapeKind::Lathe,
        ShapeKind::Mesh,
        ShapeKind::Parametric,
        ShapeKind::Plane,
        ShapeKind::Poly,
        ShapeKind::Polygon,
        ShapeKind::Prism,
        ShapeKind::Sor,
        ShapeKind::Sphere,
        ShapeKind::Superellipsoid,
        ShapeKind::Torus,
        ShapeKind::Triangle,
    ];
    /// Size of per-kind tables (`ShapeKind as usize` indexes them).
    pub const COUNT: usize = 22;

    /// Whether this kind works out each point's normal on its own (in f64, or by a search),
    /// whatever the width it is asked at: a packet then asks for its own lanes only, not all
    /// eight (a lathe's normal is a closest-point solve; asked for all eight lanes of a row,
    /// it was a third of the lathe kernel scenes' frames).
    pub fn normal_per_lane(self) -> bool {
        matches!(
            self,
            ShapeKind::Poly
                | ShapeKind::Superellipsoid
                | ShapeKind::Prism
                | ShapeKind::Lathe
                | ShapeKind::Sor
                | ShapeKind::Blob
                | ShapeKind::Julia
                | ShapeKind::Isosurface
                | ShapeKind::Parametric
        )
    }

    pub fn name(self) -> &'static str {
        match self {
            ShapeKind::Sphere | ShapeKind::Ellipsoid => "Sphere",
            ShapeKind::Box => "Box",
            ShapeKind::Triangle | ShapeKind::SmoothTriangle => "Triangle",
            ShapeKind::Polygon => "Polygon",
            ShapeKind::Plane => "Plane",
            ShapeKind::Cone => "Cone/Cylinder",
            ShapeKind::Disc => "Disc",
            ShapeKind::Torus => "Torus",
            ShapeKind::Csg => "CSG",
            ShapeKind::Poly => "Quadric/Poly",
            ShapeKind::Superellipsoid => "Superellipsoid",
            ShapeKind::Prism => "Prism",
            ShapeKind::Lathe => "Lathe",
            ShapeKind::Sor => "Sor",
            ShapeKind::Blob => "Blob",
            ShapeKind::Julia => "Julia Fractal",
            ShapeKind::Mesh => "Mesh",
            ShapeKind::HeightField => "Height Field",
            ShapeKind::Isosurface => "Isosurface",
            ShapeKind::Parametric => "Parametric",
        }
    }
}
