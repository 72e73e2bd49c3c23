#include "jtracer/serializer.hpp"

#include "language/number_text.hpp"

#include <string_view>

namespace jt {

namespace {

using lang::number_text;
using lang::vector_text;

class Writer {
  public:
    std::string text;

    void open(std::string_view keyword) {
        indent();
        text.append(keyword).append(" {\n");
        ++depth_;
    }
    void close() {
        --depth_;
        indent();
        text.append("}\n");
    }
    void property(std::string_view name, std::string_view value) {
        indent();
        text.append(name).append(": ").append(value).append(";\n");
    }
    void number(std::string_view name, double v) { property(name, number_text(v)); }
    void whole(std::string_view name, int v) { property(name, std::to_string(v)); }
    void vector(std::string_view name, const Vec3& v) { property(name, vector_text(v)); }
    void string(std::string_view name, std::string_view s) {
        std::string quoted = "\"";
        for (char c : s) quoted += (c >= 0x20 && c < 0x7f && c != '"') ? c : '_';
        property(name, quoted + '"');
    }
    void blank() { text += '\n'; }

  private:
    void indent() { text.append(static_cast<std::size_t>(depth_) * 4, ' '); }
    int depth_ = 0;
};

void write_settings(Writer& w, const RenderSettings& s) {
    w.open("render_settings");
    w.whole("width", s.width);
    w.whole("height", s.height);
    w.whole("recurse_depth", s.recurse_depth);
    w.string("filename", s.filename);
    if (!s.active_camera.empty()) w.string("active_camera", s.active_camera);
    w.vector("background", s.background);
    w.vector("ambient_light", s.ambient_light);
    if (s.samples != 1) w.whole("samples", s.samples);  // extension: only when used
    w.close();
}

void write_camera(Writer& w, const Camera& c) {
    w.open("perspective_camera");
    w.string("name", c.name);
    w.vector("position", c.position);
    w.vector("look_at", c.look_at);
    w.vector("up", c.up);
    w.number("aspect", c.aspect);
    w.number("fov", c.fov);
    w.close();
}

void write_material(Writer& w, const Material& m) {
    w.open("material");
    w.vector("pigment", m.pigment);
    w.vector("ambient", m.ambient);
    w.vector("diffuse", m.diffuse);
    w.vector("specular", m.specular);
    w.number("diffuse_k", m.diffuse_k);
    w.number("specular_k", m.specular_k);
    w.number("reflection", m.reflection);
    w.close();
}

void write_transforms(Writer& w, const std::vector<TransformOp>& ops) {
    if (ops.empty()) return;
    w.open("transform");
    for (const TransformOp& op : ops) {
        switch (op.kind) {
            case TransformKind::translate:
                w.vector("translate", op.vector);
                break;
            case TransformKind::scale:
                w.vector("scale", op.vector);
                break;
            case TransformKind::xrotate:
                w.number("xrotate", op.degrees);
                break;
            case TransformKind::yrotate:
                w.number("yrotate", op.degrees);
                break;
            case TransformKind::zrotate:
                w.number("zrotate", op.degrees);
                break;
        }
    }
    w.close();
}

void write_primitive(Writer& w, const Primitive& p) {
    if (auto* sphere = std::get_if<Sphere>(&p.shape)) {
        w.open("sphere");
        w.vector("center", sphere->center);
        w.number("radius", sphere->radius);
    } else if (auto* plane = std::get_if<Plane>(&p.shape)) {
        w.open("plane");
        w.vector("normal", plane->normal);
        w.number("distance", plane->distance);
    } else {
        const auto& cylinder = std::get<Cylinder>(p.shape);
        w.open("cylinder");
        w.number("radius", cylinder.radius);
        w.number("height", cylinder.height);
    }
    write_material(w, p.material);
    write_transforms(w, p.transforms);
    w.close();
}

}  // namespace

std::string serialize_scene(const Scene& scene) {
    Writer w;
    w.text = "# Written by JTracer.\n\n";
    write_settings(w, scene.settings);
    w.blank();
    w.open("cameras");
    for (const Camera& c : scene.cameras) write_camera(w, c);
    w.close();
    w.blank();
    w.open("scene");
    for (const Primitive& p : scene.primitives) write_primitive(w, p);
    for (const PointLight& light : scene.lights) {
        w.open("point_light");
        w.vector("position", light.position);
        w.vector("intensity", light.intensity);
        w.close();
    }
    w.close();
    return std::move(w.text);
}

}  // namespace jt
