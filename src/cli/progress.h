#pragma once
// A one-line progress indicator on stderr, shown only when stderr is a terminal so that logs and
// pipes stay clean.
#include <cstddef>
#include <string>

namespace cli {

class Progress {
public:
    explicit Progress(std::string label);
    ~Progress();  // clears the line
    Progress(const Progress&) = delete;
    Progress& operator=(const Progress&) = delete;

    void update(std::size_t done, std::size_t total, const std::string& detail = {});

private:
    std::string label_;
    bool visible_;
};

}  // namespace cli
