use super::*;
use crate::geometry::Shape;
use crate::ray::Ray;
use glam::{DMat4, DVec4};

#[test]
fn exit_of_a_scaled_component_under_a_sheared_object_is_found() {
    let c = DMat4::from_cols(
        DVec4::new(0.09529261505396067, 0.0, -1.4945968793782234, 0.0),
        DVec4::new(0.0, 0.5540787194962102, 0.0, 0.0),
        DVec4::new(1.3713110567472688, 0.0, 0.08743214873044615, 0.0),
        DVec4::new(-2.6497761158876614, 1.170133407895424, 2.054917809969966, 1.0),
    );
    let o = DMat4::from_cols(
        DVec4::new(-0.49852049978142554, -0.5314563376586563, -0.2136960016432724, 0.0),
        DVec4::new(0.21109212447103107, 0.48231689975555486, -1.6919554963398564, 0.0),
        DVec4::new(1.2346917853696977, -1.0946429457253226, -0.1580012479401576, 0.0),
        DVec4::new(-2.930510186393658, -1.5948111370265299, 0.3968558249894665, 1.0),
    );
    let comp = Component {
        shape: ComponentShape::Sphere {
            center: DVec3::new(0.13906372058727823, 2.624080659647907, 2.024039751757491),
            radius: 0.5913713267652868,
        },
        strength: 1.4992542031824312,
        blob_from_component: DAffine3::from_mat4(c),
    };
    let b = Blob::new(DAffine3::from_mat4(o), &[comp], 0.5475846990092451);
    let ray = Ray::new(Vec3::new(0.85596853, -2.2951937, -4.48347), Vec3::new(-0.75869477, -0.54732114, -0.35330126));
    let t0 = b.intersect(&ray, 0.0, f32::INFINITY).expect("the ray enters the blob");
    // The exit, searched for from the entry as CSG and the parity test do.
    assert!(b.intersect(&ray, t0, f32::INFINITY).is_some());
}
