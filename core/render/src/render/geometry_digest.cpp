#include "render/prepared_scene.hpp"

#include "jtracer/file_stamp.hpp"
#include "jtracer/texture.hpp"

#include <bit>
#include <type_traits>

namespace jt {

namespace {

// Two independent multiply-xorshift lanes over every number that decides the
// geometry: 128 bits, so that an accidental match is out of the question.
struct Digester {
    std::uint64_t a = 0x9E3779B97F4A7C15ull;
    std::uint64_t b = 0xC2B2AE3D27D4EB4Full;

    void add(std::uint64_t v) {
        a = (a ^ v) * 0xFF51AFD7ED558CCDull;
        a ^= a >> 33;
        b = (b + v) * 0x94D049BB133111EBull;
        b ^= b >> 31;
    }
    void add(double v) { add(std::bit_cast<std::uint64_t>(v)); }
    void add(const std::string& s) {
        add(static_cast<std::uint64_t>(s.size()));
        for (char c : s) add(static_cast<std::uint64_t>(static_cast<unsigned char>(c)));
    }
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
