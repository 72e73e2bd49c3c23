#pragma once
// The scene the structure-edit tests change: comments inside and outside
// blocks, blank lines between blocks, one-line blocks, a camera named as
// active_camera, and transforms both inline and one operation per line.

namespace jt::test {

inline constexpr const char* kEditScene = R"(# A scene for structure edits.
render_settings {
    width: 64;
    height: 48;
    active_camera: "side";
}

cameras {
    perspective_camera { name: "front"; position: <0, 0, 5>; }  # one line
    perspective_camera {
        name: "side";   # the active one
        position: <5, 0, 0>;
        look_at: <0,0,0>;
    }
}

scene {
    # A red ball.
    sphere {
        radius: 1;  # unit
        material { pigment: <1, 0, 0>; }
        transform { translate: <0, 1, 0>; yrotate: 30; }
    }

    plane { distance: -1; }

    cylinder {
        transform {
            translate: <1, 0, 0>;   # first
            scale: <1, 2, 1>;
            zrotate: 10;
        }
    }

    point_light {
        position: <0, 5, 5>;
        intensity: <1, 1, 1>;
    }
}
)";

}  // namespace jt::test
