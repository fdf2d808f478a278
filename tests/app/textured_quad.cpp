#include "textured_quad.h"

#include <fstream>

#include "render/image.h"

namespace app::test {

std::filesystem::path write_textured_quad(const std::filesystem::path& folder, const std::string& texture) {
    std::filesystem::remove_all(folder);
    std::filesystem::create_directories(folder);
    render::Image halves{kHalvesSide, kHalvesSide, std::vector<std::uint8_t>(4 * kHalvesSide * kHalvesSide, 0)};
    for (int i = 0; i < kHalvesSide * kHalvesSide; ++i) {
        const bool left = i % kHalvesSide < kHalvesSide / 2;
        halves.rgba[4 * static_cast<std::size_t>(i) + (left ? 0 : 2)] = 255;
        halves.rgba[4 * static_cast<std::size_t>(i) + 3] = 255;
    }
    std::ofstream(folder / "halves.png", std::ios::binary) << render::encode_png(halves);
    std::ofstream(folder / "quad.mtl") << "newmtl skin\nKd 0 1 0\nmap_Kd " << texture << '\n';
    std::ofstream(folder / "quad.obj") << "mtllib quad.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
                                          "usemtl skin\nf 1/1 2/2 3/3\nf 1/1 3/3 4/4\n";
    return folder / "quad.obj";
}

}  // namespace app::test
