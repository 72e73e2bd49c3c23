#include "model/object_drag.hpp"

#include "jtracer/affine.hpp"
#include "jtracer/model_cache.hpp"
#include "jtracer/schema.hpp"
#include "jtracer/texture.hpp"
#include "jtracer/transform_edit.hpp"
#include "jtracer/value_text.hpp"
#include "model/app_actions.hpp"
#include "model/document_edits.hpp"
#include "model/field_sources.hpp"
#include "model/picking.hpp"

#include <glm/geometric.hpp>

#include <cmath>

namespace jt::view {

namespace {

// Each shape's centre in its object space.
Vec3 local_centre(const Scene&, const Sphere& s) {
    return s.center;
}
Vec3 local_centre(const Scene&, const Plane& p) {
    return unit_length(p.normal).value_or(Vec3{0.0}) * p.distance;
}
Vec3 local_centre(const Scene&, const Cylinder& c) {
    return {0.0, c.height * 0.5, 0.0};
}
Vec3 local_centre(const Scene&, const Triangle& t) {
    return (t.a + t.b + t.c) / 3.0;
}
Vec3 local_centre(const Scene& scene, const Mesh& mesh) {
    const auto model = shared_model(asset_path(scene, mesh.file), scene.asset_folder);
    if (!model) return Vec3{0.0};
    const ModelBox box = model_box(**model);
    return box.empty() ? Vec3{0.0} : (box.lower + box.upper) * 0.5;
}

std::string target_name(const Scene& scene, const Selection& target) {
    const BlockRef block{
        target.kind == Selection::Kind::light ? BlockKind::light : BlockKind::primitive,
        static_cast<std::size_t>(target.index)};
    return block_name(scene, block);
}

// Where the drag grabs the target: the point of it under the press, or its centre.
std::optional<Vec3> grabbed_point(AppState& state, const PreparedFrame& frame,
                                  const Selection& target, const ImagePoint& at) {
    const Scene& scene = state.doc.scene;
    const auto index = static_cast<std::size_t>(target.index);
    if (target.kind == Selection::Kind::light) return scene.lights[index].position;
    const int x = static_cast<int>(std::floor(at.x)), y = static_cast<int>(std::floor(at.y));
    if (const std::optional<PickedPrimitive> hit = pick_primitive(frame, x, y);
        hit && hit->primitive == target.index)
        if (const std::optional<CameraRay> ray = camera_ray(frame, {x + 0.5, y + 0.5}))
            return ray->origin + ray->direction * hit->distance;
    return object_centre(scene, scene.primitives[index]);
}

// A plane's normal in world space, or nothing when its transform leaves it out.
std::optional<Vec3> world_normal(const Primitive& primitive) {
    const Plane* plane = shape_if<Plane>(&primitive.shape);
    if (!plane) return std::nullopt;
    const auto transform = object_transform(primitive.transforms);
    const ObjectTransform* t = std::get_if<ObjectTransform>(&transform);
    if (!t) return std::nullopt;
    return unit_length(t->normal_matrix * plane->normal);
}

// The value under image point `at`, or nothing when its ray misses the plane.
std::optional<Vec3> value_at(const ObjectDrag& drag, const ImagePoint& at, bool one_axis) {
    const std::optional<Vec3> delta = drag_delta(*drag.frame, drag.plane, drag.press, at);
    if (!delta) return std::nullopt;
    const Vec3 move = drag.only_along ? along(*delta, *drag.only_along)
                      : one_axis      ? along_largest_axis(*delta)
                                      : *delta;
    return moved_value(drag.start, move, drag.pixel_size);
}

void say_moved(AppState& state, const ObjectDrag& drag, const char* verb) {
    const std::string name = target_name(state.doc.scene, drag.target);
    const bool light = drag.target.kind == Selection::Kind::light;
    state.message = std::string(verb) + " " + name + (light ? ": position " : ": translate ") +
                    vector_text(drag.written);
}

// Something else replaced the document since the drag's last write (a reload
// from disk, a text edit taken in): the drag stops where it is.
bool overtaken(AppState& state) {
    if (state.drags.object->generation == state.history.scene_generation) return false;
    state.drags.object.reset();
    state.message = "The scene changed: the move stopped";
    return true;
}

// Puts `value` into the document; false (the drag given back) when the text
// edit that adds the translate fails.
bool write_value(AppState& state, const Vec3& value) {
    ObjectDrag& drag = *state.drags.object;
    const auto index = static_cast<std::size_t>(drag.target.index);
    if (drag.target.kind == Selection::Kind::light) {
        state.doc.scene.lights[index].position = value;
    } else if (drag.adds_translate) {
        const TransformOp op{TransformKind::translate, value, 0.0};
        const Expected<void> added = rewrite_text(state, [&](const SceneText& s) {
            return add_transform_op(s, index, s.scene.primitives[index].transforms.size(), op);
        });
        if (!added) {
            const std::string why = added.error().message;
            cancel_object_drag(state);
            state.message = why;
            return false;
        }
        drag.adds_translate = false;
    } else {
        state.doc.scene.primitives[index].transforms.back().vector = value;
    }
    drag.written = value;
    drag.changed = true;
    note_command_edit(state.history, state.doc);
    drag.generation = state.history.scene_generation;
    return true;
}

}  // namespace

std::optional<Vec3> object_centre(const Scene& scene, const Primitive& primitive) {
    const auto transform = object_transform(primitive.transforms);
    const ObjectTransform* t = std::get_if<ObjectTransform>(&transform);
    if (!t) return std::nullopt;
    const Vec3 local =
        visit_shape([&](const auto& shape) { return local_centre(scene, shape); }, primitive.shape);
    return apply_point(t->to_world, local);
}

bool start_object_drag(AppState& state, const ImagePoint& at, double marker_radius) {
    state.drags.object.reset();
    if (!state.doc.loaded || state.doc.draft) {
        state.message =
            state.doc.draft ? "Not moved: the text has errors; fix them first" : "No scene is open";
        return false;
    }
    const std::shared_ptr<const PreparedFrame> frame = shown_frame(state);
    if (!frame) {
        state.message = "Not moved: the image is not ready yet";
        return false;
    }
    Selection target = current_selection(state.view, state.doc.scene);
    if (target.kind == Selection::Kind::none) {
        select_at(state, at.x, at.y, marker_radius);
        target = current_selection(state.view, state.doc.scene);
    }
    if (target.kind == Selection::Kind::none) {
        state.message = "Nothing to move: Alt+drag on an object or light, or select one first";
        return false;
    }
    const std::optional<Vec3> grabbed = grabbed_point(state, *frame, target, at);
    const std::optional<DragPlane> plane =
        grabbed ? plane_facing_camera(*frame, *grabbed) : std::nullopt;
    const std::optional<double> pixel = plane ? pixel_size_on(*frame, *plane, at) : std::nullopt;
    const std::string name = target_name(state.doc.scene, target);
    if (!pixel) {
        state.message = "Not moved: " + name +
                        (grabbed ? " is behind the camera" : " is left out of the render");
        return false;
    }
    ObjectDrag drag;
    drag.target = target;
    drag.frame = frame;
    drag.press = at;
    drag.plane = *plane;
    drag.pixel_size = *pixel;
    const auto index = static_cast<std::size_t>(target.index);
    if (target.kind == Selection::Kind::light) {
        // A position written as a name or an expression is the text's to
        // change (docs/language.md §15.2): a move would be refused by Save.
        const FieldSource position = field_source(
            state.doc, block_source(state.doc, {EditedBlock::Kind::light, index}), "position");
        if (read_only(position)) {
            // Say what the value is and the two ways out: change the value
            // where it is set, or write a position in its place.
            std::string why = "Not moved: " + name + "'s position is " +
                              computed_from(state.doc, position) +
                              ". To drag the light, write a position <x, y, z> in its place in "
                              "the text editor (T)";
            if (position.origin == FieldOrigin::name)
                why += ", or change " + std::string(written_text(state.doc, position)) +
                       " where it is set";
            state.message = why;
            return false;
        }
        drag.start = state.doc.scene.lights[index].position;
    } else {
        const Primitive& p = state.doc.scene.primitives[static_cast<std::size_t>(target.index)];
        drag.only_along = world_normal(p);
        if (shape_is<Plane>(p.shape) && !drag.only_along) {
            state.message = "Not moved: " + name + " is left out of the render";
            return false;
        }
        // A last translate written as a name or an expression stays as
        // written: the move is a translate of its own after it.
        const BlockSource* source = block_source(state.doc, {EditedBlock::Kind::primitive, index});
        const bool translate_last =
            !p.transforms.empty() && p.transforms.back().kind == TransformKind::translate &&
            !read_only(transform_field_source(state.doc, source, p.transforms.size() - 1));
        drag.adds_translate = !translate_last;
        drag.start = translate_last ? p.transforms.back().vector : Vec3{0.0};
    }
    drag.written = drag.start;
    drag.before = version_of(state.doc);
    drag.generation = state.history.scene_generation;
    state.drags.object = std::move(drag);
    state.message = "Moving " + name +
                    (state.drags.object->only_along
                         ? " along its normal (a plane cannot move within itself); Esc cancels"
                         : " (Shift: along one axis; Esc cancels)");
    return true;
}

void drag_object_to(AppState& state, const ImagePoint& at, bool one_axis,
                    std::chrono::steady_clock::time_point now) {
    if (!state.drags.object || overtaken(state)) return;
    ObjectDrag& drag = *state.drags.object;
    const std::optional<Vec3> value = value_at(drag, at, one_axis);
    if (!value || *value == drag.written) return;
    if (drag.changed && now - drag.last_write < kDragWriteInterval) return;
    if (!write_value(state, *value)) return;
    state.drags.object->last_write = now;
    say_moved(state, *state.drags.object, "Moving");
}

void finish_object_drag(AppState& state, const ImagePoint& at, bool one_axis) {
    if (!state.drags.object || overtaken(state)) return;
    if (const std::optional<Vec3> value = value_at(*state.drags.object, at, one_axis);
        value && *value != state.drags.object->written && !write_value(state, *value))
        return;
    const ObjectDrag drag = std::move(*state.drags.object);
    state.drags.object.reset();
    if (drag.written == drag.start) {
        if (drag.changed) {
            restore_version(state.doc, drag.before);
            note_command_edit(state.history, state.doc);
        }
        state.message = "Not moved: let go where it started";
        return;
    }
    state.history.undo.record(drag.before);
    say_moved(state, drag, "Moved");
    state.message += " (Save scene to keep it)";
}

void cancel_object_drag(AppState& state) {
    if (!state.drags.object) return;
    const ObjectDrag drag = std::move(*state.drags.object);
    state.drags.object.reset();
    if (drag.changed && drag.generation == state.history.scene_generation) {
        restore_version(state.doc, drag.before);
        note_command_edit(state.history, state.doc);
    }
    state.message = "Move cancelled";
}

}  // namespace jt::view
