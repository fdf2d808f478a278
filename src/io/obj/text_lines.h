#pragma once
// Splitting file text into lines the way every OBJ-family reader here counts them: a line ends at
// "\n", "\r\n" or a lone "\r" (classic Mac files), so CR-only files read like any other and line
// numbers in messages match what an editor shows.
#include <cstddef>
#include <cstring>
#include <string_view>

namespace rgbio {

// Calls f(line_number, content) for each line, numbered from 1, without its line break. Each break
// character is searched with memchr, and a search result is kept until passed, so the work stays
// linear whichever of the two characters a file uses.
template <class F>
void for_each_line(std::string_view text, F&& f) {
    const char* p = text.data();
    const char* const end = p + text.size();
    auto next = [end](const char* from, char c) {
        const void* found = std::memchr(from, c, static_cast<std::size_t>(end - from));
        return found ? static_cast<const char*>(found) : end;
    };
    const char* lf = next(p, '\n');
    const char* cr = next(p, '\r');
    std::size_t number = 1;
    while (p < end) {
        if (lf < p) lf = next(p, '\n');
        if (cr < p) cr = next(p, '\r');
        const char* stop = cr < lf ? cr : lf;
        f(number++, std::string_view(p, static_cast<std::size_t>(stop - p)));
        p = stop + (stop == end ? 0 : (stop == cr && stop + 1 == lf) ? 2 : 1);
    }
}

}  // namespace rgbio
