#pragma once
// Each model file read once and shared: by the validator, which reports its
// errors at the `file` string, and by every prepared scene and every instance
// that uses it. A file whose size or modification time changed is read again.

#include "jtracer/model_file.hpp"

#include <filesystem>
#include <memory>

namespace jt {

// read_model's result for (file, folder, file_materials), from memory when an unchanged copy
// is held. The few models used last stay held after their last user lets go,
// so that validating a scene and then rendering it reads each file once.
Expected<std::shared_ptr<const Model>> shared_model(const std::filesystem::path& file,
                                                    const std::filesystem::path& folder,
                                                    bool file_materials = false);

// The next shared_model of `file` reads it again even if its stamp has not
// moved (a user's Reload: a copy tool may keep the time, and a glTF's buffer
// files have stamps of their own). Models already shared stay as they are.
void forget_model(const std::filesystem::path& file);

}  // namespace jt
