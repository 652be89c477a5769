// Kernel benchmark: clipped_by, a sphere clipped by a box that cuts off its top and its front
// (the inside shows).
#version 3.7;
#include "kernel_common.inc"
KGrid(sphere { <0, 0.45, 0>, 0.45 clipped_by { box { <-0.5, -0.1, -0.25>, <0.5, 0.7, 0.5> } } })
