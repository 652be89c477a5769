//! Shapes and their ray tests, one file per kind. Every routine answers the nearest `t` in an
//! open interval `(t_min, t_max)`; normals are computed afterwards, only for the winning hit.

pub mod cuboid;
pub mod lanes;
pub mod plane;
pub mod polygon;
pub mod precise;
pub mod ray;
pub mod sphere;
pub mod triangle;
