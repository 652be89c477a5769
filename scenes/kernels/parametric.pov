// Kernel benchmark: parametric, a sphere of radius 0.4 (u around, v from pole to pole).
// precompute 20 (the most POV-Ray allows): with 12, POV-Ray takes about 2 minutes at 640x480.
#version 3.7;
#include "kernel_common.inc"
KGrid(parametric {
  function { 0.4 * cos(u) * cos(v) }
  function { 0.4 * sin(v) }
  function { 0.4 * sin(u) * cos(v) }
  <0, -pi / 2>, <2 * pi, pi / 2>
  contained_by { box { -0.42, 0.42 } }
  accuracy 0.005
  precompute 20 x, y, z
  translate y * 0.42 })
