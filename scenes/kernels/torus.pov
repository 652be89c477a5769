// Kernel benchmark: torus, major radius 0.35, minor 0.1225 (the same torus as quartic.pov).
#version 3.7;
#include "kernel_common.inc"
KGrid(torus { 0.35, 0.1225 translate y * 0.1225 })
