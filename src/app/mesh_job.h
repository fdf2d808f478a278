#pragma once
// Whole-mesh work that may take seconds (flood fill, automatic LOD), done a time slice per frame so
// the window keeps drawing and the user can cancel. The editor treats every job alike.
#include <chrono>
#include <string>

namespace app {

class MeshJob {
public:
    virtual ~MeshJob() = default;
    // Works for about `slice`; returns false once finished.
    virtual bool step(std::chrono::microseconds slice) = 0;
    // In [0, 1].
    virtual float progress() const = 0;
    virtual bool changed() const = 0;
    virtual std::string label() const = 0;
};

}  // namespace app
