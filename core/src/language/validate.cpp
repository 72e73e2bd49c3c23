#include "jtracer/validate.hpp"

#include "language/number_text.hpp"

#include <glm/geometric.hpp>

#include <cmath>
#include <string>

namespace jt {
using lang::vector_text;
}

namespace jt {

namespace {

template <class T>
const BlockSource* at(const std::vector<BlockSource>& sources, const std::vector<T>& items,
                      std::size_t i) {
    // Sources are parallel to the scene's lists only when the scene came
    // straight from the parser; a scene edited in code may differ.
    return sources.size() == items.size() ? &sources[i] : nullptr;
}

bool finite(const Vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

class Validator {
  public:
    Validator(const Scene& scene, const SceneSource& source) : scene_(scene), source_(source) {}

    std::vector<Diagnostic> run() {
        check_settings();
        check_cameras();
        check_primitives();
        check_lights();
        if (!source_.scene && scene_.primitives.empty() && scene_.lights.empty()) {
            warning({}, "no scene block: the image will show only the background");
        }
        return std::move(out_);
    }

  private:
    void error(SourcePos pos, std::string message) {
        out_.push_back({Severity::error, pos, std::move(message)});
    }
    void warning(SourcePos pos, std::string message) {
        out_.push_back({Severity::warning, pos, std::move(message)});
    }
    // Where a block's property `name` was written (its last occurrence), else the block's keyword.
    SourcePos where(const BlockSource* block, std::string_view name) const {
        if (!block) return {};
        const auto properties = properties_of(source_, *block);
        for (auto it = properties.rbegin(); it != properties.rend(); ++it) {
            if (it->name == name) return it->value_span.pos;
        }
        return block->keyword_span.pos;
    }

    const BlockSource* settings_block() const {
        return source_.render_settings ? &*source_.render_settings : nullptr;
    }

    void check_settings() {
        const RenderSettings& s = scene_.settings;
        const BlockSource* block = settings_block();
        for (auto [name, value] : {std::pair{"width", s.width}, std::pair{"height", s.height}}) {
            if (value == 0) {
                error(where(block, name), std::string("the image ") + name + " is 0: set '" + name +
                                              "' in render_settings or pass --" + name);
            } else if (value < 0 || value > 65535) {
                error(where(block, name), std::string("the image ") + name + " " +
                                              std::to_string(value) + " is outside 1..65535");
            }
        }
        if (s.width > 0 && s.height > 0 && bmp_file_size(s.width, s.height) > 0xFFFFFFFFull) {
            error(where(block, "height"), "a " + std::to_string(s.width) + " x " +
                                              std::to_string(s.height) +
                                              " image does not fit in a BMP file (4 GiB at most)");
        }
        if (s.recurse_depth < 0 || s.recurse_depth > 256) {
            error(where(block, "recurse_depth"), "'recurse_depth' must be from 0 to 256");
        }
        if (s.samples < 1 || s.samples > 1024) {
            error(where(block, "samples"), "'samples' must be from 1 to 1024");
        }
        if (s.filename.empty()) error(where(block, "filename"), "'filename' must not be empty");
        if (!s.active_camera.empty() && !scene_.cameras.empty() &&
            active_camera_index(scene_) == 0 && scene_.cameras[0].name != s.active_camera) {
            warning(where(block, "active_camera"),
                    "no camera is named \"" + s.active_camera + "\": using the first camera" +
                        (scene_.cameras[0].name.empty() ? std::string()
                                                        : " (\"" + scene_.cameras[0].name + "\")"));
        }
    }

    void check_cameras() {
        if (scene_.cameras.empty()) {
            error({}, "every render needs a camera: add cameras { perspective_camera { ... } }");
            return;
        }
        const RenderSettings& s = scene_.settings;
        for (std::size_t i = 0; i < scene_.cameras.size(); ++i) {
            const Camera& c = scene_.cameras[i];
            const BlockSource* block = at(source_.cameras, scene_.cameras, i);
            const std::string which =
                c.name.empty() ? "camera " + std::to_string(i + 1) : "camera \"" + c.name + "\"";
            if (!finite(c.position) || !finite(c.look_at) || !finite(c.up)) {
                error(where(block, "position"), which + " has a non-finite vector");
                continue;
            }
            const Vec3 view = c.look_at - c.position;
            if (view == Vec3(0.0)) {
                error(where(block, "look_at"),
                      which + ": 'look_at' equals 'position', so the camera looks nowhere");
            } else if (glm::length(glm::cross(glm::normalize(view), c.up)) <=
                       1e-9 * glm::length(c.up)) {
                error(where(block, "up"), which + ": 'up' " + vector_text(c.up) +
                                              " is parallel to the view direction " +
                                              vector_text(view) + " (or zero)");
            }
            if (!(c.fov > 0.0 && c.fov < 180.0)) {
                error(where(block, "fov"), which + ": 'fov' must be between 0 and 180 degrees");
            }
            if (!(c.aspect > 0.0) || !std::isfinite(c.aspect)) {
                error(where(block, "aspect"), which + ": 'aspect' must be greater than 0");
            } else if (s.width > 0 && s.height > 0) {
                double image = static_cast<double>(s.width) / s.height;
                if (std::abs(c.aspect - image) > 0.01 * image) {
                    warning(where(block, "aspect"),
                            which + ": 'aspect' " + lang::number_text(c.aspect) +
                                " differs from width/height = " + lang::number_text(image) +
                                " by more than 1%, so the image will look stretched");
                }
            }
        }
    }

    void check_primitives() {
        for (std::size_t i = 0; i < scene_.primitives.size(); ++i) {
            const Primitive& p = scene_.primitives[i];
            const BlockSource* block = at(source_.primitives, scene_.primitives, i);
            check_shape(p.shape, block);
            check_material(p.material, block);
            check_transforms(p, block);
        }
    }

    void check_shape(const Shape& shape, const BlockSource* block) {
        if (auto* sphere = std::get_if<Sphere>(&shape)) {
            if (!(sphere->radius > 0.0) || !std::isfinite(sphere->radius))
                error(where(block, "radius"), "a sphere's 'radius' must be greater than 0");
        } else if (auto* plane = std::get_if<Plane>(&shape)) {
            if (plane->normal == Vec3(0.0) || !finite(plane->normal))
                error(where(block, "normal"), "a plane's 'normal' must not be zero");
        } else if (auto* cylinder = std::get_if<Cylinder>(&shape)) {
            if (!(cylinder->radius > 0.0) || !std::isfinite(cylinder->radius))
                error(where(block, "radius"), "a cylinder's 'radius' must be greater than 0");
            if (!(cylinder->height > 0.0) || !std::isfinite(cylinder->height))
                error(where(block, "height"), "a cylinder's 'height' must be greater than 0");
        }
    }

    void check_material(const Material& m, const BlockSource* block) {
        SourcePos pos = block ? block->keyword_span.pos : SourcePos{};
        if (!(m.diffuse_k > 0.0)) error(pos, "'diffuse_k' must be greater than 0");
        if (!(m.specular_k > 0.0)) error(pos, "'specular_k' must be greater than 0");
        if (!(m.reflection >= 0.0 && m.reflection <= 1.0))
            error(pos, "'reflection' must be from 0 to 1");
    }

    // The scale op number k of a primitive is the k-th op property across its transform blocks.
    SourcePos op_position(const BlockSource* block, std::size_t k) const {
        if (!block) return {};
        for (const BlockSource& child : children_of(source_, *block)) {
            if (child.keyword != "transform") continue;
            const auto ops = properties_of(source_, child);
            if (k < ops.size()) return ops[k].name_span.pos;
            k -= ops.size();
        }
        return block->keyword_span.pos;
    }

    void check_transforms(const Primitive& p, const BlockSource* block) {
        for (std::size_t k = 0; k < p.transforms.size(); ++k) {
            const TransformOp& op = p.transforms[k];
            if (op.kind == TransformKind::scale &&
                (op.vector.x == 0.0 || op.vector.y == 0.0 || op.vector.z == 0.0)) {
                warning(op_position(block, k),
                        "'scale' " + vector_text(op.vector) +
                            " has a zero component: it flattens the primitive to nothing; it is "
                            "left out");
            }
        }
    }

    void check_lights() {
        for (std::size_t i = 0; i < scene_.lights.size(); ++i) {
            const PointLight& light = scene_.lights[i];
            if (!finite(light.position)) {
                const BlockSource* block = at(source_.lights, scene_.lights, i);
                error(where(block, "position"), "a point_light's 'position' must be finite");
            }
        }
    }

    const Scene& scene_;
    const SceneSource& source_;
    std::vector<Diagnostic> out_;
};

}  // namespace

int active_camera_index(const Scene& scene) {
    if (scene.cameras.empty()) return -1;
    if (!scene.settings.active_camera.empty()) {
        for (std::size_t i = 0; i < scene.cameras.size(); ++i) {
            if (scene.cameras[i].name == scene.settings.active_camera) return static_cast<int>(i);
        }
    }
    return 0;
}

unsigned long long bmp_file_size(int width, int height) {
    if (width <= 0 || height <= 0) return 54;
    unsigned long long row = (3ull * static_cast<unsigned>(width) + 3) & ~3ull;
    return 54 + row * static_cast<unsigned>(height);
}

std::vector<Diagnostic> validate_scene(const Scene& scene, const SceneSource& source) {
    return Validator(scene, source).run();
}

}  // namespace jt
