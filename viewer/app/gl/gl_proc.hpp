#pragma once
// The signature every platform's "get GL function by name" shares, without
// pulling in any GL header.

namespace jt::view {

using GlProc = void (*)();
using GlProcLoader = GlProc (*)(const char* name);

}  // namespace jt::view
