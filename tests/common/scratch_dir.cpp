#include "common/scratch_dir.hpp"

#include <unistd.h>

#include <algorithm>

namespace jt::test {

namespace fs = std::filesystem;

fs::path make_scratch_dir(std::string_view label) {
    std::string name = "jtracer";
    if (!label.empty()) name.append("_").append(label);
    if (const auto* info = testing::UnitTest::GetInstance()->current_test_info())
        name.append("_").append(info->test_suite_name()).append("_").append(info->name());
    name.append("_").append(std::to_string(::getpid()));
    std::replace(name.begin(), name.end(), '/', '_');  // parameterised tests: "Suite/Name/0"
    const fs::path dir = fs::temp_directory_path() / name;
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

ScratchDir::ScratchDir(std::string_view label) : path_(make_scratch_dir(label)) {}

ScratchDir::~ScratchDir() {
    if (testing::Test::HasFailure()) return;
    std::error_code ec;
    // A test may have taken permissions away to provoke an error.
    fs::permissions(path_, fs::perms::owner_all, fs::perm_options::add, ec);
    fs::remove_all(path_, ec);
}

std::vector<std::string> ScratchTest::files() const {
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(dir))
        names.push_back(entry.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
}

}  // namespace jt::test
