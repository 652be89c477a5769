// Kernel benchmark: blob of two cylinder components (a cross).
#version 3.7;
#include "kernel_common.inc"
KGrid(blob { threshold 0.4
  cylinder { <-0.35, 0.25, 0>, <0.35, 0.25, 0>, 0.4, 1 }
  cylinder { <0, 0.25, -0.35>, <0, 0.25, 0.35>, 0.4, 1 } })
