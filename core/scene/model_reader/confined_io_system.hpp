#pragma once
// The files a model may open: Assimp's default file access, refused for any
// path outside one folder (after resolving `..` and symbolic links) and for
// any file over kMaxModelFileBytes. A hostile model cannot read /etc/passwd
// through a glTF buffer URI or an OBJ `mtllib ../../x`.
// A relative name a model asks for (a LightWave scene's `LoadObjectLayer 1
// cube.lwo`, an Ogre mesh's material file) is taken from the model's own
// folder, as the tools that wrote it mean it, never from the working
// directory: a scene reads the same files wherever it is rendered from.

#include <assimp/DefaultIOSystem.h>

#include <filesystem>
#include <string>
#include <vector>

namespace jt {

class ConfinedIOSystem : public Assimp::DefaultIOSystem {
  public:
    // `folder`: the only folder whose files may be opened; `model`: the
    // model file, whose folder relative names are taken from.
    ConfinedIOSystem(std::filesystem::path folder, const std::filesystem::path& model);

    // Material libraries (.mtl) are then never opened, nor a refusal kept:
    // for reading again a model whose library broke the import while its
    // materials are not wanted.
    void leave_out_libraries() { leave_out_libraries_ = true; }

    bool Exists(const char* file) const override;
    Assimp::IOStream* Open(const char* file, const char* mode = "rb") override;

    // Why the first refused file was refused, as a phrase after the model's
    // name ("refers to 'x.mtl', outside the folder '/y'"), or "" when none
    // was. The import may have gone on without it.
    const std::string& refusal() const { return refusal_; }

    // The material libraries (.mtl) opened, in order, and why the first that
    // could not be opened was not ("" when none failed): the model's
    // materials are read from them (model_reader/model_materials.hpp).
    const std::vector<std::filesystem::path>& libraries() const { return libraries_; }
    const std::string& library_failure() const { return library_failure_; }

    // Whether `file` lies inside the folder (textures are confined as the
    // files Assimp opens are); the folder, canonical.
    bool contains(const std::filesystem::path& file) const;
    const std::filesystem::path& folder() const { return folder_; }

  private:
    // True when `file` may be opened; else keeps why not as the refusal.
    bool allowed(const char* file) const;
    // `file` as opened: a relative name taken from the model's folder.
    std::filesystem::path resolved(const char* file) const;
    // `file` as messages name it: relative to the model's folder when it lies
    // below it by name, else as asked.
    std::string shown(const char* file) const;

    std::filesystem::path folder_;  // canonical
    std::filesystem::path base_;    // the model's folder, absolute
    mutable std::string refusal_;   // Exists is const in Assimp's interface
    std::vector<std::filesystem::path> libraries_;
    std::string library_failure_;
    bool leave_out_libraries_ = false;
};

}  // namespace jt
