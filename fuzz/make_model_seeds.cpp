// Turns model files into model_fuzzer inputs: each file's bytes after the byte
// that picks its extension (fuzz/invariants.hpp, model_extensions). Files of
// other kinds are passed over.
//   make_model_seeds OUT_FOLDER MODEL_FILE...
#include "invariants.hpp"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

int main(int argc, char** argv) {
    if (argc < 2) {
        std::fprintf(stderr, "usage: make_model_seeds OUT_FOLDER MODEL_FILE...\n");
        return 2;
    }
    namespace fs = std::filesystem;
    const fs::path out = argv[1];
    fs::create_directories(out);
    int written = 0;
    for (int i = 2; i < argc; ++i) {
        const fs::path file = argv[i];
        std::string ext = file.extension().string();
        if (ext.empty()) continue;
        ext.erase(0, 1);
        for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
        const auto& kinds = jt::fuzz::model_extensions;
        const auto kind = std::find(kinds.begin(), kinds.end(), ext);
        if (kind == kinds.end()) continue;
        std::ifstream in(file, std::ios::binary);
        std::ofstream seed(out / (std::to_string(written++) + "-" + file.filename().string()),
                           std::ios::binary);
        seed.put(static_cast<char>(kind - kinds.begin()));
        seed << in.rdbuf();
    }
    std::printf("%d model seeds in %s\n", written, out.c_str());
    return 0;
}
