#include "jtracer/validate.hpp"

#include "jtracer/affine.hpp"
#include "jtracer/bmp.hpp"
#include "jtracer/model_cache.hpp"
#include "jtracer/schema.hpp"
#include "jtracer/smooth_normals.hpp"
#include "jtracer/texture.hpp"
#include "jtracer/value_text.hpp"
#include "language/validation.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <mutex>
#include <string>

namespace jt {

namespace {

template <class T>
const BlockSource* at(const std::vector<BlockSource>& sources, const std::vector<T>& items,
                      std::size_t i) {
    // Sources are parallel to the scene's lists only when the scene came
    // straight from the parser; a scene edited in code may differ.
    return sources.size() == items.size() ? &sources[i] : nullptr;
}

// Primitives are checked in chunks of this many on the caller's threads
// (ChunkRunner) once there are more than two chunks: enough work a chunk that
// handing it out costs nothing next to it (a sphere takes about 80 ns), and
// enough chunks for any number of threads to share a million primitives.
constexpr std::size_t primitives_a_chunk = 8192;

// The properties of a block whose default value is out of range, in the
// schema's order: the only ones a primitive as parsed can hold out of range
// (ValidateOptions::primitives_as_parsed), as a property left unwritten keeps
// its default unchecked.
template <class Block>
const std::vector<const PropertySpec<Block>*>& defaults_out_of_range() {
    static const std::vector<const PropertySpec<Block>*> found = [] {
        std::vector<const PropertySpec<Block>*> out;
        const Block fresh{};
        for (const PropertySpec<Block>& property : schema_of<Block>().properties)
            if (value_problem(property, fresh)) out.push_back(&property);
        return out;
    }();
    return found;
}

// What a model file gave when read.
struct ModelVerdict {
    std::string error;  // "": it loads
    std::vector<std::string> warnings;
    std::size_t corners = 0, corners_without_normals = 0;
    std::shared_ptr<const Model> model;  // null when it does not load
};
// What each image or model file gave when read, shared by the chunks checking
// primitives: each file is read once however many primitives name it. The
// mutex is held while a file is read, so that a second chunk naming it waits
// for the verdict rather than reading it again; reading calls no ChunkRunner,
// so a thread holding it never waits for work of its own.
struct FileVerdicts {
    std::mutex mutex;
    std::map<std::pair<std::string, bool>, ModelVerdict> models;  // by file and materials
    std::map<std::string, std::string> images;  // by file: the problem, "" if none
};

class Validator {
  public:
    Validator(const Scene& scene, const SceneSource& source, const ValidateOptions& options,
              FileVerdicts& files)
        : scene_(scene), source_(source), options_(options), files_(files) {}

    lang::Validation run() {
        check_settings();
        check_background_map();
        check_cameras();
        const std::size_t before_primitives = out_.size();
        check_primitives();
        const bool about_primitives = out_.size() != before_primitives;
        check_lights();
        if (!source_.scene && scene_.primitives.empty() && scene_.lights.empty()) {
            warning({}, "no scene block: the image will show only the background");
        }
        return {std::move(out_), about_primitives};
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

    // The same for a primitive's material property: its last occurrence across
    // the primitive's material blocks, else the primitive's keyword.
    SourcePos where_material(const BlockSource* primitive, std::string_view name) const {
        if (!primitive) return {};
        const auto children = children_of(source_, *primitive);
        for (auto child = children.rbegin(); child != children.rend(); ++child) {
            if (child->keyword != schema_of<Material>().keyword) continue;
            const auto properties = properties_of(source_, *child);
            for (auto it = properties.rbegin(); it != properties.rend(); ++it)
                if (it->name == name) return it->value_span.pos;
        }
        return primitive->keyword_span.pos;
    }

    // Every property of `block` against its range (values set in code can be
    // anything; parsed ones are in range already). `which()` names the block
    // in the message ("camera 2: "), made only for a message: a name for each
    // of a million primitives was a third of the checks. `locate` finds a
    // property's position. True when all are in range.
    template <class Block, class Which, class Locate>
    bool check_values(const Block& block, Which which, Locate locate) {
        bool ok = true;
        for (const PropertySpec<Block>& property : schema_of<Block>().properties) {
            if (auto problem = value_problem(property, block)) {
                error(locate(property.name), which() + *problem);
                ok = false;
            }
        }
        return ok;
    }

    // check_values for a primitive's block: all its properties, or for a
    // primitive as parsed those whose default is out of range.
    template <class Block, class Which, class Locate>
    void check_primitive_values(const Block& block, Which which, Locate locate) {
        if (!options_.primitives_as_parsed) {
            check_values(block, which, locate);
            return;
        }
        for (const PropertySpec<Block>* property : defaults_out_of_range<Block>())
            if (auto problem = value_problem(*property, block))
                error(locate(property->name), which() + *problem);
    }

    const BlockSource* settings_block() const {
        return source_.render_settings ? &*source_.render_settings : nullptr;
    }

    void check_settings() {
        const RenderSettings& s = scene_.settings;
        const BlockSource* block = settings_block();
        const auto locate = [&](std::string_view name) { return where(block, name); };
        if (!check_values(
                s, [] { return std::string(); }, locate))
            return;
        // 0 parses (it is the default) but cannot render (docs/language.md §4.9).
        for (auto [name, value] : {std::pair{"width", s.width}, std::pair{"height", s.height}}) {
            if (value == 0) {
                error(locate(name), std::string("the image ") + name + " is 0: set '" + name +
                                        "' in render_settings");
                out_.back().setting = name;
            }
        }
        if (s.width > 0 && s.height > 0 && !fits_in_bmp(s.width, s.height)) {
            error(locate("height"), "a " + std::to_string(s.width) + " x " +
                                        std::to_string(s.height) +
                                        " image does not fit in a BMP file (4 GiB at most)");
        }
        if (!s.active_camera.empty() && !scene_.cameras.empty() &&
            active_camera_index(scene_) == 0 && scene_.cameras[0].name != s.active_camera) {
            warning(where(block, "active_camera"),
                    "no camera is named \"" + s.active_camera + "\": using the first camera" +
                        (scene_.cameras[0].name.empty() ? std::string()
                                                        : " (\"" + scene_.cameras[0].name + "\")"));
        }
    }

    // Whether the property was written in the block (any occurrence).
    bool written(const BlockSource* block, std::string_view name) const {
        if (!block) return false;
        for (const PropertySource& p : properties_of(source_, *block))
            if (p.name == name) return true;
        return false;
    }

    // The map must decode, with the render's own error, as image maps must
    // (docs/language.md §14.3); the check's decoded picture is the render's.
    void check_background_map() {
        const RenderSettings& s = scene_.settings;
        const BlockSource* block = settings_block();
        const SourcePos pos = where(block, "background_map");
        if (s.background_map.empty()) {
            // The default means "no map"; written out, "" names no file.
            if (written(block, "background_map"))
                error(pos,
                      "background_map: the file name is empty (leave 'background_map' out to "
                      "show the background colour)");
            return;
        }
        if (written(block, "background"))
            warning(where(block, "background"),
                    "'background' and 'background_map' are both set: the background map wins, "
                    "so no ray shows this colour");
        auto texture = load_texture(asset_path(scene_, s.background_map));
        if (!texture) error(pos, "background_map: " + texture.error().message);
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
            const std::string noun(schema_of<Camera>().noun);
            const std::string which =
                c.name.empty() ? noun + " " + std::to_string(i + 1) : noun + " \"" + c.name + "\"";
            if (!check_values(
                    c, [&] { return which + ": "; },
                    [&](std::string_view name) { return where(block, name); }))
                continue;
            const Vec3 view = c.look_at - c.position;
            if (view == Vec3(0.0)) {
                error(where(block, "look_at"),
                      which + ": 'look_at' equals 'position', so the camera looks nowhere");
            } else if (c.up == Vec3(0.0)) {
                error(where(block, "up"),
                      which +
                          ": 'up' is <0, 0, 0>, which gives no direction for the top of "
                          "the image");
            } else if (glm::length(glm::cross(glm::normalize(view), c.up)) <=
                       1e-9 * glm::length(c.up)) {
                error(where(block, "up"), which + ": 'up' " + vector_text(c.up) +
                                              " is parallel to the view direction " +
                                              vector_text(view));
            }
            if (s.width > 0 && s.height > 0) {
                double image = static_cast<double>(s.width) / s.height;
                if (std::abs(c.aspect - image) > 0.01 * image) {
                    warning(where(block, "aspect"),
                            which + ": 'aspect' " + number_text(c.aspect) +
                                " differs from width/height = " + number_text(image) +
                                " by more than 1%, so the image will look stretched");
                }
            }
            // Overrides (--samples) are applied before validation, so
            // `samples` here is the render's.
            if (c.aperture > 0.0 && s.samples == 1 &&
                static_cast<int>(i) == active_camera_index(scene_)) {
                warning(where(block, "aperture"),
                        which + ": 'aperture' " + number_text(c.aperture) +
                            " blurs nothing while 'samples' is 1 (one ray a pixel, through the "
                            "lens centre): set 'samples' to 16 or more");
                out_.back().setting = "samples";
            }
        }
    }

    // Each chunk's findings go to a validator of its own and are appended in
    // the chunks' order, so the list is the one a single pass would make.
    void check_primitives() {
        const std::size_t count = scene_.primitives.size();
        if (!options_.run_chunks || count <= 2 * primitives_a_chunk) {
            check_primitives(0, count);
            return;
        }
        const std::size_t chunks = (count + primitives_a_chunk - 1) / primitives_a_chunk;
        std::vector<std::vector<Diagnostic>> found(chunks);
        options_.run_chunks(chunks, [&](std::size_t chunk) {
            Validator part(scene_, source_, options_, files_);
            const std::size_t begin = chunk * primitives_a_chunk;
            part.check_primitives(begin, std::min(count, begin + primitives_a_chunk));
            found[chunk] = std::move(part.out_);
        });
        for (std::vector<Diagnostic>& part : found)
            out_.insert(out_.end(), std::make_move_iterator(part.begin()),
                        std::make_move_iterator(part.end()));
    }

    void check_primitives(std::size_t begin, std::size_t end) {
        for (std::size_t i = begin; i < end; ++i) {
            const Primitive& p = scene_.primitives[i];
            const BlockSource* block = at(source_.primitives, scene_.primitives, i);
            const auto which = [&] {
                return std::string(keyword_of(p.shape)) + " " + std::to_string(i + 1) + ": ";
            };
            visit_shape(
                [&](const auto& shape) {
                    check_primitive_values(
                        shape, which, [&](std::string_view name) { return where(block, name); });
                },
                p.shape);
            check_primitive_values(p.material, which, [&](std::string_view name) {
                return where_material(block, name);
            });
            // As parsed, an operation is there only if the parser read it.
            const std::size_t unread = options_.primitives_as_parsed ? 0 : p.transforms.size();
            for (std::size_t k = 0; k < unread; ++k) {
                const TransformOp& op = p.transforms[k];
                if (auto problem = value_problem(transform_op(op.kind).property, op))
                    error(op_position(block, k), which() + *problem);
            }
            check_transforms(p, block);
            check_image_map(p.material, block);
            if (const auto* triangle = shape_if<Triangle>(&p.shape))
                check_triangle(*triangle, block, which);
            if (const auto* mesh = shape_if<Mesh>(&p.shape)) check_mesh(*mesh, block, which());
        }
    }

    // A triangle of zero area is left out (docs/language.md §13.5).
    template <class Which>
    void check_triangle(const Triangle& t, const BlockSource* block, Which which) {
        if (glm::cross(t.b - t.a, t.c - t.a) != Vec3(0.0)) return;
        warning(block ? block->keyword_span.pos : SourcePos{},
                which() + "its corners " + vector_text(t.a) + ", " + vector_text(t.b) + ", " +
                    vector_text(t.c) + " lie on one line (zero area): it is left out");
    }

    // The model must load and hold a triangle; each file is read once
    // (model_cache.hpp), so the render that follows reads it no more.
    void check_mesh(const Mesh& mesh, const BlockSource* block, const std::string& which) {
        if (mesh.file.empty()) return;  // check_values reported it
        const SourcePos pos = where(block, "file");
        const bool file_materials = mesh.materials == kFileMaterials;
        std::unique_lock lock(files_.mutex);
        auto known = files_.models.find({mesh.file, file_materials});
        if (known == files_.models.end()) {
            ModelVerdict verdict;
            auto model =
                shared_model(asset_path(scene_, mesh.file), scene_.asset_folder, file_materials);
            if (!model) {
                verdict.error = model.error().message;
            } else {
                verdict.model = *model;
                verdict.warnings = model_warnings(**model);
                verdict.corners = 3 * (*model)->triangles.size();
                verdict.corners_without_normals = corners_without_normals(**model);
            }
            known = files_.models.emplace(std::pair(mesh.file, file_materials), verdict).first;
        }
        // An entry, once made, never changes or moves.
        const ModelVerdict& verdict = known->second;
        lock.unlock();
        if (!verdict.error.empty()) error(pos, which + verdict.error);
        for (const std::string& w : verdict.warnings)
            warning(pos, which + "'" + mesh.file + "' " + w);
        check_smooth_angle(mesh, block, which, verdict);
    }
    // Language 1.1 shades a triangle flat when the file lacks a normal at any
    // of its corners; smooth_angle generates them (docs/language.md §14.4).
    void check_smooth_angle(const Mesh& mesh, const BlockSource* block, const std::string& which,
                            const ModelVerdict& verdict) {
        if (mesh.shading == kFlatShading && mesh.smooth_angle) {
            warning(where(block, "smooth_angle"),
                    which + "'smooth_angle' does nothing with shading \"flat\": it is ignored");
        }
        // Made here to report a model past the work bound at the angle; the
        // render takes them from memory (smooth_normals.hpp).
        if (mesh.shading == kSmoothShading && mesh.smooth_angle && verdict.model &&
            verdict.corners_without_normals > 0) {
            const auto normals = shared_corner_normals(verdict.model, *mesh.smooth_angle);
            if (!normals)
                error(where(block, "smooth_angle"),
                      which + "'" + mesh.file + "': " + normals.error().message);
        }
        if (mesh.shading == kSmoothShading && !mesh.smooth_angle &&
            verdict.corners_without_normals > 0) {
            warning(where(block, "file"),
                    which + "'" + mesh.file + "' has no normal at " +
                        std::to_string(verdict.corners_without_normals) + " of its " +
                        std::to_string(verdict.corners) +
                        " triangle corners: their triangles are shaded flat; smooth_angle (such "
                        "as 60) generates normals there");
        }
    }
    // The picture must decode (docs/language.md §13.4), with the error the
    // render would give; each file is decoded once however many materials
    // name it, and the render takes it from memory (texture.hpp).
    void check_image_map(const Material& m, const BlockSource* block) {
        if (m.finish->image_map.empty()) return;
        const SourcePos pos = where_material(block, "image_map");
        if (m.finish->checker)
            warning(pos, "'image_map' and 'checker' are both set: the image map wins");
        std::unique_lock lock(files_.mutex);
        auto known = files_.images.find(m.finish->image_map);
        if (known == files_.images.end()) {
            auto texture = load_texture(asset_path(scene_, m.finish->image_map));
            known =
                files_.images.emplace(m.finish->image_map, texture ? "" : texture.error().message)
                    .first;
        }
        const std::string& problem = known->second;
        lock.unlock();
        if (!problem.empty()) error(pos, "image_map: " + problem);
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

    // The renderer leaves out exactly the primitives geometry/affine.hpp's rule
    // does: a warning at each zero scale, else at the op that leaves the doubles.
    void check_transforms(const Primitive& p, const BlockSource* block) {
        if (p.transforms.empty()) return;
        bool flattened = false;
        for (std::size_t k = 0; k < p.transforms.size(); ++k) {
            if (!flattens(p.transforms[k])) continue;
            flattened = true;
            warning(op_position(block, k),
                    "'scale' " + vector_text(p.transforms[k].vector) +
                        " has a zero component: it flattens the primitive to nothing; it is left "
                        "out");
        }
        if (flattened) return;
        const auto placed = object_transform(p.transforms);
        if (const auto* left_out = std::get_if<LeftOut>(&placed))
            warning(op_position(block, left_out->op),
                    "the transform leaves the range of double precision here (magnitudes past "
                    "about 1e308): the primitive is left out");
    }

    void check_lights() {
        for (std::size_t i = 0; i < scene_.lights.size(); ++i) {
            const BlockSource* block = at(source_.lights, scene_.lights, i);
            check_values(
                scene_.lights[i],
                [&] {
                    return std::string(schema_of<PointLight>().noun) + " " + std::to_string(i + 1) +
                           ": ";
                },
                [&](std::string_view name) { return where(block, name); });
        }
    }

    const Scene& scene_;
    const SceneSource& source_;
    const ValidateOptions& options_;
    FileVerdicts& files_;
    std::vector<Diagnostic> out_;
};

lang::Validation validate(const Scene& scene, const SceneSource& source,
                          const ValidateOptions& options) {
    FileVerdicts files;
    return Validator(scene, source, options, files).run();
}

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

bool fits_in_bmp(int width, int height) {
    return bmp_file_size(width, height) <= kMaxBmpFileBytes;
}

std::vector<Diagnostic> validate_scene(const Scene& scene, const SceneSource& source,
                                       const ValidateOptions& options) {
    return validate(scene, source, options).diagnostics;
}

lang::Validation lang::validate_scene_parts(const Scene& scene, const SceneSource& source,
                                            const ValidateOptions& options) {
    return validate(scene, source, options);
}

}  // namespace jt
