#include "render/prepared_scene.hpp"

#include "jtracer/digest.hpp"
#include "jtracer/file_stamp.hpp"
#include "jtracer/texture.hpp"

#include <type_traits>

namespace jt {

namespace {

// The digest with the vectors and strings the geometry is made of.
struct Digester : Digest128 {
    using Digest128::add;
    void add(const std::string& s) { Digest128::add(std::string_view(s)); }
    void add(const Vec3& v) {
        add(v.x);
        add(v.y);
        add(v.z);
    }
};

}  // namespace

GeometryDigest digest_geometry(const Scene& scene) {
    const std::vector<Primitive>& primitives = scene.primitives;
    Digester d;
    for (const Primitive& p : primitives) {
        d.add(static_cast<std::uint64_t>(p.shape.index()));
        if (const auto* s = shape_if<Sphere>(&p.shape)) {
            d.add(s->center);
            d.add(s->radius);
        } else if (const auto* c = shape_if<Cylinder>(&p.shape)) {
            d.add(c->radius);
            d.add(c->height);
        } else if (const auto* l = shape_if<Plane>(&p.shape)) {
            d.add(l->normal);
            d.add(l->distance);
        } else if (const auto* t = shape_if<Triangle>(&p.shape)) {
            for (const Vec3* v : {&t->a, &t->b, &t->c, &t->uv_a, &t->uv_b, &t->uv_c}) d.add(*v);
        } else if (const auto* m = shape_if<Mesh>(&p.shape)) {
            d.add(m->file);
            d.add(m->shading);
            d.add(m->materials);  // "file" reads another model
            // A model file changed on disk is a new geometry.
            const FileStamp stamp = file_stamp(asset_path(scene, m->file));
            d.add(stamp.inode);
            d.add(stamp.size);
            d.add(static_cast<std::uint64_t>(stamp.mtime_ns));
        }
        d.add(static_cast<std::uint64_t>(p.transforms.size()));
        for (const TransformOp& op : p.transforms) {
            d.add(static_cast<std::uint64_t>(op.kind));
            d.add(op.vector);
            d.add(op.degrees);
        }
    }
    return {d.a, d.b, primitives.size()};
}

}  // namespace jt
