#include "io/input_file.hpp"

#include "core/text.hpp"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <stdexcept>

namespace rt {

std::string read_input_file(const std::string& path, const std::string& kind, const limits::Range& size_limit) {
    namespace fs = std::filesystem;
    const std::string what = one_line(kind + " " + path) + ": ";
    std::error_code ec;
    const fs::file_status status = fs::status(path, ec);
    if (status.type() == fs::file_type::not_found) throw std::runtime_error(what + "no such file");
    if (ec) throw std::runtime_error(what + ec.message());
    if (status.type() == fs::file_type::directory) throw std::runtime_error(what + "is a directory");
    // Not a FIFO, a device or /dev/zero: those can be endless.
    if (status.type() != fs::file_type::regular) throw std::runtime_error(what + "is not a regular file");
    const auto size = fs::file_size(path, ec);
    if (ec) throw std::runtime_error(what + ec.message());
    if (!limits::contains(size_limit, double(size)))
        throw std::runtime_error(what + limits::refuse(size_limit, double(size)));
    std::ifstream in(path, std::ios::binary);
    if (!in) throw std::runtime_error(what + "cannot open: " + std::strerror(errno));
    std::string bytes(size, '\0');
    in.read(bytes.data(), std::streamsize(size));
    if (std::size_t(in.gcount()) != size) throw std::runtime_error(what + "cannot read the whole file");
    return bytes;
}

}  // namespace rt
