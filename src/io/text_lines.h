#pragma once
// Splitting file text into lines the way every OBJ-family reader here counts them: a line ends at
// "\n", "\r\n" or a lone "\r" (classic Mac files), so CR-only files read like any other and line
// numbers in messages match what an editor shows.
#include <cstddef>
#include <string_view>

namespace rgbio {

// Calls f(line_number, content) for each line, numbered from 1, without its line break.
template <class F>
void for_each_line(std::string_view text, F&& f) {
    std::size_t number = 1;
    while (!text.empty()) {
        const std::size_t end = std::min(text.find_first_of("\r\n"), text.size());
        f(number++, text.substr(0, end));
        std::size_t next = end;
        if (next < text.size()) next += text.compare(next, 2, "\r\n") == 0 ? 2 : 1;
        text.remove_prefix(next);
    }
}

}  // namespace rgbio
