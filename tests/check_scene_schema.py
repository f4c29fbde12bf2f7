#!/usr/bin/python3
"""Checks docs/scene.schema.json: it is a valid draft 2020-12 schema, every example scene
under scenes/ conforms to it, and documents the loader refuses are refused by it too.

Usage: check_scene_schema.py [SOURCE_DIR]   (default: the folder above this script)
Needs the jsonschema module (Debian: python3-jsonschema). Exits non-zero on failure.
"""
import copy
import json
import pathlib
import sys

import jsonschema

# A scene using every part of the format (the example of docs/scene-format.md).
VALID = {
    "camera": {"type": "perspective", "position": [0, 1, 6.8], "look_at": [0, 1, 0], "up": [0, 1, 0],
               "fov": 19.5, "resolution": [512, 512], "aperture_radius": 0, "focus_distance": 6.8},
    "materials": {
        "white": {"type": "diffuse", "albedo": [0.725, 0.71, 0.68]},
        "wood": {"type": "diffuse", "albedo": {"texture": "textures/wood.png"}},
        "glass": {"type": "dielectric", "ior": 1.5},
        "frosted": {"type": "dielectric", "ior": 1.5, "roughness": 0.3},
        "pane": {"type": "dielectric", "ior": 1.5, "thin": True},
        "mirror": {"type": "mirror", "reflectance": [0.95, 0.95, 0.95]},
        "metal": {"type": "conductor", "reflectance": [0.9, 0.6, 0.3], "roughness": 0.2},
        "gloss": {"type": "plastic", "albedo": [0.1, 0.2, 0.6], "ior": 1.5, "roughness": 0.05},
        "varnish": {"type": "coated_diffuse", "albedo": [0.6, 0.3, 0.1], "ior": 1.5, "roughness": 0.1},
        "paper": {"type": "diffuse_transmission", "reflectance": [0.4, 0.4, 0.4], "transmittance": [0.5, 0.5, 0.45]},
        "hair": {"type": "hair", "eumelanin": 0.7, "beta_m": 0.25},
        "velvet": {"type": "measured", "file": "brdfs/velvet.bsdf"},
        "paint": {"type": "coated_conductor", "ior": 1.5, "roughness": 0.05,
                  "conductor": {"metal": "Al", "roughness": 0.3}},
        "packed": {"type": "conductor", "reflectance": [0.9, 0.9, 0.9],
                   "roughness": {"texture": "textures/orm.png", "channel": "g"}},
    },
    "shapes": [
        {"type": "quad", "origin": [-1, 0, -1], "edge_u": [2, 0, 0], "edge_v": [0, 0, 2], "material": "white",
         "alpha": {"texture": "textures/leaf.png", "channel": "a"}, "alpha_cutoff": 0.5},
        {"type": "sphere", "center": [0.4, 0.3, 0.2], "radius": 0.3, "material": "glass",
         "flip_normals": False},
        {"type": "mesh", "file": "meshes/bunny.obj", "material": "white",
         "transform": {"scale": 0.5, "rotate": {"axis": [0, 1, 0], "angle": 30}, "translate": [0, 0, 0]}},
        {"type": "mesh", "positions": [[0, 0, 0], [1, 0, 0], [0, 1, 0]], "indices": [0, 1, 2],
         "normals": [[0, 0, 1], [0, 0, 1], [0, 0, 1]], "uvs": [[0, 0], [1, 0], [0, 1]], "material": "white",
         "transform": {"matrix": [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1]}},
        {"type": "quad", "origin": [-0.25, 1.98, -0.25], "edge_u": [0.5, 0, 0], "edge_v": [0, 0, 0.5],
         "material": "white", "emission": [17, 12, 4]},
        {"type": "instance", "object": "pebble", "transform": {"translate": [0.5, 0, 0.5]}},
        {"type": "curves", "file": "hair/tuft.hair", "basis": "bezier", "material": "hair"},
        {"type": "curves", "strands": [[[0, 0, 0, 0.01], [0, 0.3, 0.1], [0, 0.6, 0.1], [0.1, 1, 0]]], "width": 0.002,
         "basis": "catmull-rom", "profile": "flat", "material": "hair"},
    ],
    "objects": {"pebble": {"shapes": [{"type": "sphere", "center": [0, 0.05, 0], "radius": 0.05, "material": "white"}]}},
    "lights": [
        {"type": "point", "position": [0, 1.5, 0], "intensity": [5, 5, 5]},
        {"type": "spot", "position": [0, 1.9, 0], "direction": [0, -1, 0], "intensity": [10, 10, 10],
         "cone_angle": 30, "falloff_angle": 25},
        {"type": "directional", "direction": [0, -1, -0.3], "irradiance": [3, 3, 3]},
        {"type": "environment", "radiance": [0.1, 0.1, 0.1]},
        {"type": "point", "position": [0, 1.5, 0], "intensity": [5, 5, 5], "image": "profile.exr",
         "layout": "equal_area", "rotate": {"axis": [1, 0, 0], "angle": 90}},
    ],
    "render": {"integrator": "sppm", "passes": 64, "photons_per_pass": 200000, "time_limit": 0,
               "initial_radius": "auto", "alpha": 0.6667, "max_depth": 8, "seed": 1, "kernel": "uniform",
               "exposure": 0, "direct": "light_sampling"},
}


def edited(edit):
    doc = copy.deepcopy(VALID)
    edit(doc)
    return doc


def set_path(*path_and_value):
    *path, value = path_and_value

    def edit(doc):
        target = doc
        for key in path[:-1]:
            target = target[key]
        target[path[-1]] = value
    return edit


def delete(*path):
    def edit(doc):
        target = doc
        for key in path[:-1]:
            target = target[key]
        del target[path[-1]]
    return edit


# (description, edit) pairs: each edited document must fail validation.
INVALID = [
    ("missing camera", delete("camera")),
    ("unknown top-level field", set_path("colour", 1)),
    ("unknown render field", set_path("render", "pases", 64)),
    ("unknown shape field", set_path("shapes", 1, "colour", [1, 0, 0])),
    ("unknown material field", set_path("materials", "white", "albedoo", [1, 1, 1])),
    ("field of another material type", set_path("materials", "glass", "albedo", [1, 1, 1])),
    ("rough thin dielectric", set_path("materials", "glass", {"type": "dielectric", "thin": True, "roughness": 0.2})),
    ("thin not a boolean", set_path("materials", "glass", "thin", 1)),
    ("negative radius", set_path("shapes", 1, "radius", -1)),
    ("radius as a string", set_path("shapes", 1, "radius", "big")),
    ("unknown shape type", set_path("shapes", 0, "type", "cone")),
    ("instance without an object", delete("shapes", 5, "object")),
    ("instance with a material", set_path("shapes", 5, "material", "white")),
    ("instance inside an object", set_path("objects", "pebble", "shapes", 0, {"type": "instance", "object": "pebble"})),
    ("object without shapes", set_path("objects", "pebble", "shapes", [])),
    ("unknown light type", set_path("lights", 0, "type", "area")),
    ("resolution 0", set_path("camera", "resolution", [0, 512])),
    ("alpha 1.5", set_path("render", "alpha", 1.5)),
    ("passes not an integer", set_path("render", "passes", 1.5)),
    ("initial_radius not auto", set_path("render", "initial_radius", "big")),
    ("auto_radius_photons 0", set_path("render", "auto_radius_photons", 0)),
    ("albedo above 1", set_path("materials", "white", "albedo", [0.5, 1.2, 0.5])),
    ("transmittance above 1", set_path("materials", "paper", "transmittance", [0.5, 1.2, 0.5])),
    ("coated field on a sheet", set_path("materials", "paper", "ior", 1.5)),
    ("hair with two absorptions", set_path("materials", "hair", "sigma_a", [0.1, 0.2, 0.3])),
    ("measured without a file", delete("materials", "velvet", "file")),
    ("measured file outside", set_path("materials", "velvet", "file", "../velvet.bsdf")),
    ("curves with emission", set_path("shapes", -2, "emission", [1, 1, 1])),
    ("negative emission", set_path("shapes", 4, "emission", [1, -1, 1])),
    ("absolute path", set_path("shapes", 2, "file", "/etc/passwd")),
    ("'..' path", set_path("shapes", 2, "file", "meshes/../../x.obj")),
    ("empty path", set_path("shapes", 2, "file", "")),
    ("texture outside", set_path("materials", "wood", "albedo", {"texture": "../x.png"})),
    ("file and positions", set_path("shapes", 2, "positions", [[0, 0, 0]])),
    ("matrix and scale", set_path("shapes", 3, "transform", {"matrix": [1] * 16, "scale": 2})),
    ("no shapes", set_path("shapes", [])),
    ("cone angle above 90", set_path("lights", 1, "cone_angle", 95)),
    ("environment image with radiance", set_path("lights", 3, "image", "sky.exr")),
    ("environment scale without image", set_path("lights", 3, "scale", 2)),
    ("environment without radiance or image", delete("lights", 3, "radiance")),
    ("unknown environment layout",
     set_path("lights", 3, {"type": "environment", "image": "sky.exr", "layout": "cube"})),
    ("negative environment scale", set_path("lights", 3, {"type": "environment", "image": "sky.exr", "scale": -1})),
    ("zero scale", set_path("shapes", 2, "transform", "scale", 0)),
    ("unknown metal", set_path("materials", "metal", {"type": "conductor", "metal": "Xx"})),
    ("metal and reflectance", set_path("materials", "metal", {"type": "conductor", "metal": "Au",
                                                               "reflectance": [1, 1, 1]})),
    ("eta without k", set_path("materials", "metal", {"type": "conductor", "eta": [0.2, 0.9, 1.1]})),
    ("coated conductor without its metal", set_path("materials", "metal", {"type": "coated_conductor", "ior": 1.5})),
    ("a type inside a coated conductor's metal", set_path("materials", "metal", {"type": "coated_conductor",
                                                                                "conductor": {"type": "conductor"}})),
    ("coated conductor's metal by two forms", set_path("materials", "metal", {"type": "coated_conductor",
                                                                              "conductor": {"metal": "Au", "eta": [1, 1, 1]}})),
    ("unknown named spectrum", set_path("materials", "metal", {"type": "conductor", "eta": "metal-Fe-eta",
                                                                "k": [1, 1, 1]})),
    ("unknown image channel", set_path("materials", "packed", "roughness", "channel", "x")),
    ("alpha_cutoff 0", set_path("shapes", 0, "alpha_cutoff", 0)),
    ("alpha_cutoff above 1", set_path("shapes", 0, "alpha_cutoff", 1.5)),
    ("remap_roughness not a boolean", set_path("materials", "metal", {"type": "conductor", "metal": "Au",
                                                                       "remap_roughness": 1})),
]


def main():
    root = pathlib.Path(sys.argv[1]) if len(sys.argv) > 1 else pathlib.Path(__file__).resolve().parent.parent
    schema = json.loads((root / "docs" / "scene.schema.json").read_text())
    jsonschema.Draft202012Validator.check_schema(schema)
    validator = jsonschema.Draft202012Validator(schema)
    passed, failures = 0, []

    def check(name, doc, should_pass):
        nonlocal passed
        errors = list(validator.iter_errors(doc))
        if should_pass and errors:
            failures.append(f"{name}: {errors[0].json_path}: {errors[0].message}")
        elif not should_pass and not errors:
            failures.append(f"{name}: accepted but should be refused")
        else:
            passed += 1

    scenes = sorted((root / "scenes").rglob("*.json"))
    if not scenes:
        failures.append("no scenes found under " + str(root / "scenes"))
    for path in scenes:
        check(str(path.relative_to(root)), json.loads(path.read_text()), True)
    check("the format example", VALID, True)
    for name, edit in INVALID:
        check("invalid: " + name, edited(edit), False)

    for f in failures:
        print("FAIL", f)
    print(f"{passed} passed, {len(failures)} failed")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
