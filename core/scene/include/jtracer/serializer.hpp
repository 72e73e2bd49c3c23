#pragma once
// Scene -> canonical .jts text.

#include "jtracer/scene.hpp"

#include <string>
#include <string_view>
#include <vector>

namespace jt {

// Canonical .jts text for `scene`: every block and property written out in a
// fixed order, each number in the shortest form that reads back exactly, so
// that parse_scene(serialize_scene(s)).scene == s for any scene the parser can
// produce. Strings keep only printable ASCII without '"' (others become '_'),
// since nothing else can be written in the language.
std::string serialize_scene(const Scene& scene);

// One block as serialize_scene writes it, one line per element with no
// indentation of its own (nested lines are indented by four spaces each
// level), for edits that insert a new block into a text.
std::vector<std::string> block_lines(const Primitive& primitive);
std::vector<std::string> block_lines(const PointLight& light);
std::vector<std::string> block_lines(const Camera& camera);
std::vector<std::string> block_lines(const Material& material);
// A transform block holding `ops`, in their order.
std::vector<std::string> transform_block_lines(const std::vector<TransformOp>& ops);
// "translate: <1, 0, 0>;": one transform operation as a statement.
std::string transform_op_statement(const TransformOp& op);

}  // namespace jt
