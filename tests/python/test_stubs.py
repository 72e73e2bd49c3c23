# The type stubs (jtracer.pyi, installed beside the module) name what the
# module has: every public function, class and attribute, and no more.
import ast
import inspect
import pathlib

import jtracer


def stub_tree():
    path = pathlib.Path(jtracer.__file__).with_name("jtracer.pyi")
    return ast.parse(path.read_text())


def public(names):
    return {n for n in names if not n.startswith("_")}


def test_stubs_name_the_module_contents():
    tree = stub_tree()
    stubbed = set()
    for node in tree.body:
        if isinstance(node, (ast.FunctionDef, ast.ClassDef)):
            stubbed.add(node.name)
        elif isinstance(node, ast.AnnAssign):
            stubbed.add(node.target.id)
    aliases = {"Image", "PathLike", "Vector", "DefineValue"}  # the stubs' own type aliases
    assert public(stubbed) - aliases == public(dir(jtracer))
    assert "__version__" in stubbed


def test_stubs_name_each_class_members():
    for node in stub_tree().body:
        if not isinstance(node, ast.ClassDef):
            continue
        cls = getattr(jtracer, node.name)
        members = set()
        for item in node.body:
            if isinstance(item, ast.FunctionDef):
                members.add(item.name)
            elif isinstance(item, ast.AnnAssign):
                members.add(item.target.id)
        if node.name == "SceneError":
            assert members == {"diagnostics"}
            continue
        assert public(members) == public(dir(cls)), node.name


def test_stubbed_render_arguments_are_the_module_ones():
    stub = next(n for n in stub_tree().body if isinstance(n, ast.ClassDef) and n.name == "Scene")
    render = next(n for n in stub.body if isinstance(n, ast.FunctionDef) and n.name == "render")
    stubbed = [a.arg for a in render.args.args][1:]
    documented = inspect.getdoc(jtracer.Scene.render).splitlines()[0]
    assert documented.startswith("render(self: jtracer.Scene, " + ", ".join(
        f"{name}: " for name in stubbed[:1]))
    for name in stubbed:
        assert f"{name}: " in documented
