#pragma once
// Bytes from a file shown in a message: quoted, shortened, and with every byte that is not
// printable ASCII written as \xNN, so that a hostile file cannot send escape sequences (or
// invisible characters) to the user's terminal through an error message.
#include <cstddef>
#include <string>
#include <string_view>

namespace rgbio {

// 'text' in single quotes, at most max_shown bytes of it (then "..."), escaped as above.
std::string quoted_file_text(std::string_view text, std::size_t max_shown = 40);

}  // namespace rgbio
