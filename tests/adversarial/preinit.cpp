// adversarial 2.2: puts code before the harness's own (a .preinit_array of its own)
// @helpers
#include <unistd.h>
namespace {
void first(int, char**, char**) { close(3); }
[[gnu::section(".preinit_array"), gnu::used]] void (*const early)(int, char**, char**) = first;
}  // namespace
// @body
    return false;
