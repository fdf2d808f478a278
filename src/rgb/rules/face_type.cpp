#include "rgb/rules/face_type.h"

namespace rgb {

const char* colour_name(Colour c) {
    switch (c) {
        case Colour::Green: return "green";
        case Colour::Red: return "red";
        case Colour::Blue: return "blue";
    }
    return "?";
}

}  // namespace rgb
