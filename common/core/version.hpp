#pragma once
namespace rt {
inline constexpr const char* kVersion = "0.1.0";
}
