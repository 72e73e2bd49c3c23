#pragma once
// stb_image's reason for a failure, as text to put in a message.
//
// stb keeps the reason of its last failure on the thread and never clears
// it, and some of its failures set none (a zlib block of the reserved type 3
// in a PNG's image data, for one): left alone, a message would quote an
// earlier failure's reason, or a null pointer, which must never reach a
// std::string. So a reader forgets the reason before each call of stb's whose
// failure it reports.

#include <stb_image.h>

#include <cstring>

namespace jt {

// Defined beside stb's implementation (stb_implementation.cpp), the one place
// its reason can be reached.
void forget_stb_failure();

// The reason stb gave since forget_stb_failure, or a plain one where it gave none.
// stb's reasons are short phrases ("bad huffman code"), mostly readable; the
// two run together into one word are put in words.
inline const char* stb_failure_reason() {
    const char* reason = stbi_failure_reason();
    if (!reason) return "its data is damaged";
    if (std::strcmp(reason, "outofdata") == 0)
        return "its data ends early (the file is truncated or damaged)";
    if (std::strcmp(reason, "outofmem") == 0) return "out of memory";
    return reason;
}

}  // namespace jt
