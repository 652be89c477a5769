// Kernel benchmark: julia_fractal, quaternion sqr (the first of POV-Ray's objects/fractal1.pov).
#version 3.7;
#include "kernel_common.inc"
KGrid(julia_fractal {
  <-0.083, 0.0, -0.83, -0.025>
  quaternion sqr
  max_iteration 8
  precision 15
  scale 0.35 translate y * 0.5 })
