#include "colors.inc"
#include "textures.inc"

camera {
    location <3, 3, -1>
    look_at <0, 1, 2>
}

light_source { <0, 4, -3> color White}
light_source { <0, 6, -4> color White}
light_source { <6, 4, -3> color White}

plane {
    <0, 1, 0>, 0
    pigment {
        checker
            color White
            color Black
    }
}

sphere {
    <0, 2, 4>, 2
    texture {
        pigment {color Orange}
        normal {bumps 0.4 scale 0.2}
        finish {phong 1}
    }
}

box {
    <-1, 0, -0.5>,
    < 1, 2, 1.5>
    pigment {
        DMFWood4
        scale 2
    }
    rotate y*(-20)
}
