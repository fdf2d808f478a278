#include "io/obj/printable_text.h"

namespace rgbio {

std::string quoted_file_text(std::string_view text, std::size_t max_shown) {
    static constexpr char kHex[] = "0123456789abcdef";
    std::string out(1, '\'');
    for (const char c : text.substr(0, max_shown)) {
        const auto byte = static_cast<unsigned char>(c);
        if (byte >= 0x20 && byte < 0x7f) {
            out += c;
        } else {
            out += "\\x";
            out += kHex[byte >> 4];
            out += kHex[byte & 15];
        }
    }
    out += text.size() > max_shown ? "...'" : "'";
    return out;
}

}  // namespace rgbio
