// Kernel benchmark: blob of three sphere components.
#version 3.7;
#include "kernel_common.inc"
KGrid(blob { threshold 0.4
  sphere { <-0.15, 0.4, 0>, 0.55, 1 }
  sphere { <0.15, 0.4, 0>, 0.55, 1 }
  sphere { <0, 0.6, 0.1>, 0.5, 1 } })
