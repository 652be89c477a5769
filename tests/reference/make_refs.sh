#!/bin/sh
# Regenerates the POV-Ray 3.7 reference images that tests/suite/reference.rs compares against.
# Needs Debian's `povray` and `povray-includes`. Run from anywhere:
#   sh tests/reference/make_refs.sh
# Renders at 640x480 without antialiasing (-A), with POV-Ray's own include library, the same
# way the textbook ran it; seed.pov is the scene as the chapter prints it.
set -eu
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
inc=/usr/share/povray-3.7/include
out="$here/expected"
mkdir -p "$out"
render() {
    povray +I"$1" +O"$out/$2.png" +W640 +H480 -A -D -V +L"$inc" +FN >/dev/null 2>&1 \
        || { echo "povray failed on $1" >&2; exit 1; }
    echo "wrote $out/$2.png"
}
render "$root/scenes/seed.pov" seed
for s in flat reflection refraction shadows interior_fade legacy gamma22 noversion cones tori csg; do
    render "$here/scenes/$s.pov" "$s"
done
for s in interior_texture; do
    render "$here/scenes/$s.pov" "$s"
done
for s in quadrics; do
    render "$here/scenes/$s.pov" "$s"
done
for s in superellipsoids; do
    render "$here/scenes/$s.pov" "$s"
done
for s in cameras_ortho cameras_ortho_plain cameras_ortho_area cameras_fisheye cameras_ultra cameras_omnimax \
    cameras_panoramic cameras_cylinder cameras_cylinder2 cameras_cylinder3 cameras_cylinder4 cameras_spherical \
    cameras_focal_blur cameras_mesh cameras_mesh_rows cameras_normal; do
    render "$here/scenes/$s.pov" "$s"
done
for s in prisms text lathes sors blobs julias isosurfaces parametrics finishes bicubic light_groups; do
    render "$here/scenes/$s.pov" "$s"
done
# heightfields.pov reads hf.pgm beside it, made by scripts/make-heightfield.py.
for s in meshes heightfields; do
    (cd "$here/scenes" && render "$here/scenes/$s.pov" "$s")
done
for s in lights_spot lights_area fog sky_sphere rainbow; do
    render "$here/scenes/$s.pov" "$s"
done
for s in patterns_simple layered patterns_function functions_pigment transforms noise_pigments noise_normals patterns_fractal patterns_spiral patterns_quilted normals_quilted slope_map layers_finish layers_normal patterns_slope; do
    render "$here/scenes/$s.pov" "$s"
done
for s in materials tiles warps warps_nested normals_warped; do
    render "$here/scenes/$s.pov" "$s"
done
# patterns_density.pov reads voxels.df3 and voxels16.df3 beside it.
(cd "$here/scenes" && render "$here/scenes/patterns_density.pov" patterns_density)
# images.pov, images_jpeg.pov, bump_maps.pov, uv_mapping.pov, uv_box.pov and texture_patterns.pov read
# ../images/*.png and *.jpg (made by tests/reference/images/make_images.py, the JPEGs by Pillow).
for s in images images_jpeg bump_maps uv_mapping uv_box texture_patterns; do
    (cd "$here/scenes" && render "$here/scenes/$s.pov" "$s")
done
