// Kernel benchmark: cylinder (capped), upright.
#version 3.7;
#include "kernel_common.inc"
KGrid(cylinder { <0, 0, 0>, <0, 0.9, 0>, 0.4 })
