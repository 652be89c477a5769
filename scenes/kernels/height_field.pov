// Kernel benchmark: height_field from a function, 64x64 samples (egg-crate bumps), not smoothed.
#version 3.7;
#include "kernel_common.inc"
KGrid(height_field {
  function 64, 64 { 0.5 + 0.5 * sin(x * 4 * pi) * sin(y * 4 * pi) }
  scale <0.9, 0.5, 0.9> translate <-0.45, 0, -0.45> })
