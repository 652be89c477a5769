// Kernel benchmark: box, turned 30 degrees about y (the general, transformed box test).
#version 3.7;
#include "kernel_common.inc"
KGrid(box { <-0.35, 0, -0.35>, <0.35, 0.8, 0.35> rotate y * 30 })
