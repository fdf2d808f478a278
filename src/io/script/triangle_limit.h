#pragma once
// How large a mesh a command may build: requests are estimated before they run
// (rgb::estimated_triangles) and refused above this limit with a message, instead of ending in
// std::bad_alloc halfway. The default follows the machine's memory.
#include <cstddef>
#include <stdexcept>
#include <string>

namespace rgb {
class Mesh;
struct LevelRequest;
}  // namespace rgb

namespace rgbio {

// About what a triangle costs while it is edited and saved (core, addresses, render copy, output
// buffers), so that the default limit leaves the machine usable.
inline constexpr std::size_t kBytesPerTriangleBudget = 160;

// Physical memory / kBytesPerTriangleBudget.
std::size_t default_triangle_limit();

class TooLarge : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// Throws TooLarge naming the estimate and the limit when the request would exceed it.
void check_request_size(const rgb::Mesh& mesh, const rgb::LevelRequest& request, std::size_t limit);
// The same for a triangle budget, which is its own estimate.
void check_budget_size(std::size_t budget, std::size_t limit);

}  // namespace rgbio
