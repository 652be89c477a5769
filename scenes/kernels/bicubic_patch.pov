// Kernel benchmark: bicubic_patch, type 1, a saddle-shaped patch 0.9 wide, raised on its corners.
#version 3.7;
#include "kernel_common.inc"
KGrid(bicubic_patch { type 1 flatness 0.01 u_steps 4 v_steps 4
  <-0.45, 0.8, -0.45>, <-0.15, 0.1, -0.45>, <0.15, 0.1, -0.45>, <0.45, 0.5, -0.45>,
  <-0.45, 0.1, -0.15>, <-0.15, 0.3, -0.15>, <0.15, 0.3, -0.15>, <0.45, 0.1, -0.15>,
  <-0.45, 0.1, 0.15>, <-0.15, 0.3, 0.15>, <0.15, 0.3, 0.15>, <0.45, 0.1, 0.15>,
  <-0.45, 0.5, 0.45>, <-0.15, 0.1, 0.45>, <0.15, 0.1, 0.45>, <0.45, 0.8, 0.45> })
