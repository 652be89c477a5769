// scenes/seed.pov written in place around @P at scale @s(1) (tests/suite/far.rs expands the
// at-forms into numbers). The floor's checker is not moved with the scene, as a user would not
// move an infinite floor's texture: it stays the same as long as P/S is an even integer on
// each axis. The other textures move with their objects.
#include "colors.inc"
#include "textures.inc"

camera {
    location @p(3, 3, -1)
    look_at @p(0, 1, 2)
}

light_source { @p(0, 4, -3) color White}
light_source { @p(0, 6, -4) color White}
light_source { @p(6, 4, -3) color White}

plane {
    <0, 1, 0>, @py(0)
    pigment {
        checker
            color White
            color Black
        scale @s(1)
    }
}

sphere {
    @p(0, 2, 4), @s(2)
    texture {
        pigment {color Orange}
        normal {bumps 0.4 scale @s(0.2) translate @P}
        finish {phong 1}
    }
}

box {
    @p(-1, 0, -0.5),
    @p( 1, 2, 1.5)
    pigment {
        DMFWood4
        scale @s(2)
        translate @P
    }
    translate -@P
    rotate y*(-20)
    translate @P
}
