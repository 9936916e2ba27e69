#!/usr/bin/env python3
"""Writes the glTF conformance corpus: a few files valid by the Khronos glTF-Validator, then
mutants of them, each breaking one rule (a wrong JSON type, a value out of range, an index past
its array, a node reachable twice, a version, a required extension, a broken GLB header...).
tests/app/gltf_validator_test.cpp runs the validator and levrt over every file and compares.

Usage: make_gltf_conformance_corpus.py OUT_DIR   (writes NAME.gltf / NAME.glb, one per case)
"""
import base64
import copy
import json
import os
import struct
import sys

POSITIONS = [0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0, 0.0]
NORMALS = [0.0, 0.0, 1.0] * 3
INDICES = [0, 1, 2]


def mesh_bytes():
    data = struct.pack("<9f", *POSITIONS) + struct.pack("<9f", *NORMALS)
    data += struct.pack("<3H", *INDICES) + b"\0\0"
    return data


def light_document():
    """Three lights (point, spot, directional) on three nodes under one parent, and a camera."""
    return {
        "asset": {"version": "2.0", "generator": "levrt conformance corpus"},
        "extensionsUsed": ["KHR_lights_punctual"],
        "extensions": {"KHR_lights_punctual": {"lights": [
            {"type": "point", "color": [1.0, 0.9, 0.8], "intensity": 20.0, "range": 10.0},
            {"type": "spot", "intensity": 30.0,
             "spot": {"innerConeAngle": 0.2, "outerConeAngle": 0.6}},
            {"type": "directional", "intensity": 2.0},
        ]}},
        "scene": 0,
        "scenes": [{"nodes": [0, 4]}],
        "nodes": [
            {"children": [1, 2, 3], "translation": [0.0, 2.0, 0.0]},
            {"extensions": {"KHR_lights_punctual": {"light": 0}}},
            {"rotation": [-0.7071068, 0.0, 0.0, 0.7071068],
             "extensions": {"KHR_lights_punctual": {"light": 1}}},
            {"extensions": {"KHR_lights_punctual": {"light": 2}}},
            {"translation": [0.0, 1.0, 6.0], "camera": 0},
        ],
        "cameras": [{"type": "perspective", "perspective": {"yfov": 0.8, "znear": 0.1}}],
    }


def mesh_document(uri=True):
    """One indexed triangle with normals and a material, lit by one point light."""
    data = mesh_bytes()
    buffer = {"byteLength": len(data)}
    if uri:
        buffer["uri"] = "data:application/octet-stream;base64," + base64.b64encode(data).decode()
    return {
        "asset": {"version": "2.0"},
        "extensionsUsed": ["KHR_lights_punctual"],
        "extensions": {"KHR_lights_punctual": {"lights": [{"type": "point", "intensity": 5.0}]}},
        "scene": 0,
        "scenes": [{"nodes": [0, 1]}],
        "nodes": [{"mesh": 0},
                  {"translation": [0.3, 0.3, 2.0],
                   "extensions": {"KHR_lights_punctual": {"light": 0}}}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1}, "indices": 2,
                                    "material": 0}]}],
        "materials": [{"pbrMetallicRoughness": {"baseColorFactor": [0.8, 0.8, 0.8, 1.0],
                                                "metallicFactor": 0.0,
                                                "roughnessFactor": 0.5}}],
        "accessors": [
            {"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
             "min": [0.0, 0.0, 0.0], "max": [1.0, 1.0, 0.0]},
            {"bufferView": 1, "componentType": 5126, "count": 3, "type": "VEC3"},
            {"bufferView": 2, "componentType": 5123, "count": 3, "type": "SCALAR"},
        ],
        "bufferViews": [{"buffer": 0, "byteLength": 36, "target": 34962},
                        {"buffer": 0, "byteOffset": 36, "byteLength": 36, "target": 34962},
                        {"buffer": 0, "byteOffset": 72, "byteLength": 6, "target": 34963}],
        "buffers": [buffer],
    }


def material_document():
    """The mesh document with a material using what levrt reads of materials: emission with its
    strength, a cut-out (MASK), doubleSided, and an orthographic camera."""
    document = mesh_document()
    document["extensionsUsed"] = document["extensionsUsed"] + ["KHR_materials_emissive_strength"]
    material = document["materials"][0]
    material["emissiveFactor"] = [1.0, 0.5, 0.0]
    material["extensions"] = {"KHR_materials_emissive_strength": {"emissiveStrength": 2.0}}
    material["alphaMode"] = "MASK"
    material["alphaCutoff"] = 0.4
    material["doubleSided"] = True
    document["cameras"] = [{"type": "orthographic",
                            "orthographic": {"xmag": 1.0, "ymag": 1.0, "znear": 0.0,
                                             "zfar": 10.0}}]
    document["nodes"].append({"translation": [0.3, 0.3, 3.0], "camera": 0})
    document["scenes"][0]["nodes"].append(2)
    return document


def glb(document, binary=b"", version=2, length_delta=0):
    text = json.dumps(document).encode()
    text += b" " * (-len(text) % 4)
    chunks = struct.pack("<I4s", len(text), b"JSON") + text
    if binary:
        binary += b"\0" * (-len(binary) % 4)
        chunks += struct.pack("<I4s", len(binary), b"BIN\0") + binary
    return struct.pack("<4sII", b"glTF", version, 12 + len(chunks) + length_delta) + chunks


def mesh_glb(**header):
    document = mesh_document(uri=False)
    return glb(document, mesh_bytes(), **header)


def edit(base, change):
    document = copy.deepcopy(base)
    change(document)
    return document


def light(document, i=0):
    return document["extensions"]["KHR_lights_punctual"]["lights"][i]


def setter(path, value):
    """A change setting document[path...] = value (a path of keys and indices)."""
    def change(document):
        target = document
        for key in path[:-1]:
            target = target[key]
        target[path[-1]] = value
    return change


def remover(path):
    def change(document):
        target = document
        for key in path[:-1]:
            target = target[key]
        del target[path[-1]]
    return change


LIGHTS = ["extensions", "KHR_lights_punctual", "lights"]


def cases():
    """(name, bytes) for every file: valid ones first, then the mutants."""
    L, M, T = light_document(), mesh_document(), material_document()
    unlit = edit(M, setter(["materials", 0, "extensions"], {"KHR_materials_unlit": {}}))
    unlit["extensionsUsed"].append("KHR_materials_unlit")
    # The mesh and its light without the light: for an empty list of lights.
    unlit_lightless = edit(M, setter(["nodes"], [{"mesh": 0}]))
    unlit_lightless["scenes"][0]["nodes"] = [0]
    files = {
        "valid_lights.gltf": L,
        "valid_mesh.gltf": M,
        "valid_mesh.glb": mesh_glb(),
        "valid_glb_named_gltf.gltf": mesh_glb(),
        "valid_json_named_glb.glb": M,
        "valid_version_2_1.gltf": edit(L, setter(["asset", "version"], "2.1")),
        "valid_min_version_2_0.gltf": edit(L, setter(["asset", "minVersion"], "2.0")),
        "valid_required_lights.gltf": edit(L, setter(["extensionsRequired"],
                                                     ["KHR_lights_punctual"])),
        "valid_zero_scale.gltf": edit(edit(M, setter(["scenes", 0, "nodes"], [0])), setter(
            ["nodes"], [{"scale": [0.0, 0.0, 0.0], "children": [1, 2]}, {"mesh": 0},
                        {"extensions": {"KHR_lights_punctual": {"light": 0}}}])),
        "valid_no_position.gltf": edit(M, setter(["meshes", 0, "primitives", 0, "attributes"],
                                                 {"NORMAL": 1})),
        "valid_range_absent.gltf": edit(L, remover(LIGHTS + [0, "range"])),
        "valid_forest.gltf": edit(L, setter(["scenes"], [{"nodes": [0, 4]}, {"nodes": [4]}])),
        "valid_material_features.gltf": T,
        "valid_unlit.gltf": unlit,
        "valid_blend.gltf": edit(M, setter(["materials", 0, "alphaMode"], "BLEND")),
        "valid_single_sided.gltf": edit(T, setter(["materials", 0, "doubleSided"], False)),
        # Doubles that round to floats levrt must still read as a valid light.
        "valid_spot_angles_one_float_apart.gltf": edit(L, setter(LIGHTS + [1, "spot"], {
            "innerConeAngle": 0.59999999999, "outerConeAngle": 0.6})),
        "valid_range_below_floats.gltf": edit(L, setter(LIGHTS + [0, "range"], 1e-300)),
        "valid_outer_cone_below_floats.gltf": edit(L, setter(LIGHTS + [1, "spot"], {
            "outerConeAngle": 5e-324})),
        "valid_orthographic_xmag_negative.gltf": edit(T, setter(["cameras", 0, "orthographic",
                                                                  "xmag"], -1.0)),
    }
    ortho = ["cameras", 0, "orthographic"]
    mutants = {
        # Wrong JSON types.
        "intensity_string": (L, setter(LIGHTS + [0, "intensity"], "50")),
        "range_string": (L, setter(LIGHTS + [0, "range"], "3")),
        "color_string": (L, setter(LIGHTS + [0, "color"], "white")),
        "type_number": (L, setter(LIGHTS + [0, "type"], 1)),
        "spot_number": (L, setter(LIGHTS + [1, "spot"], 0.5)),
        "light_index_string": (L, setter(["nodes", 1, "extensions", "KHR_lights_punctual",
                                          "light"], "0")),
        "translation_string": (L, setter(["nodes", 0, "translation"], [0, "2", 0])),
        "mesh_index_float": (M, setter(["nodes", 0, "mesh"], 0.5)),
        "byte_length_string": (M, setter(["bufferViews", 0, "byteLength"], "36")),
        "version_number": (L, setter(["asset", "version"], 2.0)),
        "scenes_object": (L, setter(["scenes"], {"nodes": [0]})),
        "metallic_string": (M, setter(["materials", 0, "pbrMetallicRoughness",
                                       "metallicFactor"], "0")),
        "yfov_string": (L, setter(["cameras", 0, "perspective", "yfov"], "0.8")),
        # Values out of range.
        "range_zero": (L, setter(LIGHTS + [0, "range"], 0)),
        "range_negative": (L, setter(LIGHTS + [0, "range"], -1.0)),
        "intensity_negative": (L, setter(LIGHTS + [0, "intensity"], -5.0)),
        "color_above_one": (L, setter(LIGHTS + [0, "color"], [2.0, 0.0, 0.0])),
        "color_two_values": (L, setter(LIGHTS + [0, "color"], [1.0, 1.0])),
        "light_type_area": (L, setter(LIGHTS + [0, "type"], "area")),
        "light_type_missing": (L, remover(LIGHTS + [0, "type"])),
        "outer_cone_above_half_pi": (L, setter(LIGHTS + [1, "spot", "outerConeAngle"], 2.0)),
        "inner_cone_above_outer": (L, setter(LIGHTS + [1, "spot", "innerConeAngle"], 0.7)),
        "translation_two_values": (L, setter(["nodes", 0, "translation"], [0.0, 2.0])),
        "rotation_three_values": (L, setter(["nodes", 2, "rotation"], [0.0, 0.0, 0.0])),
        "matrix_fifteen_values": (L, setter(["nodes", 0, "matrix"], [1.0] * 15)),
        "matrix_projective": (edit(L, remover(["nodes", 0, "translation"])), setter(
            ["nodes", 0, "matrix"], [1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0,
                                     0.0, 0.0, 1.0, 0.5, 0.0, 2.0, 0.0, 1.0])),
        "matrix_shear": (M, setter(["nodes", 0, "matrix"], [1.0, 0.0, 0.0, 0.0,
                                                            0.5, 1.0, 0.0, 0.0,
                                                            0.0, 0.0, 1.0, 0.0,
                                                            0.0, 0.0, 0.0, 1.0])),
        "matrix_and_translation": (L, setter(["nodes", 0, "matrix"], [1.0, 0.0, 0.0, 0.0,
                                                                      0.0, 1.0, 0.0, 0.0,
                                                                      0.0, 0.0, 1.0, 0.0,
                                                                      0.0, 2.0, 0.0, 1.0])),
        "base_colour_above_one": (M, setter(["materials", 0, "pbrMetallicRoughness",
                                             "baseColorFactor"], [2.0, 0.0, 0.0, 1.0])),
        "roughness_above_one": (M, setter(["materials", 0, "pbrMetallicRoughness",
                                           "roughnessFactor"], 1.5)),
        "yfov_zero": (L, setter(["cameras", 0, "perspective", "yfov"], 0.0)),
        "camera_type_fisheye": (L, setter(["cameras", 0, "type"], "fisheye")),
        "mode_seven": (M, setter(["meshes", 0, "primitives", 0, "mode"], 7)),
        "component_type_5124": (M, setter(["accessors", 0, "componentType"], 5124)),
        "accessor_type_vec5": (M, setter(["accessors", 0, "type"], "VEC5")),
        "accessor_count_zero": (M, setter(["accessors", 0, "count"], 0)),
        "accessor_count_past_view": (M, setter(["accessors", 0, "count"], 30)),
        "byte_stride_three": (M, setter(["bufferViews", 0, "byteStride"], 3)),
        "sampler_wrap_unknown": (M, setter(["samplers"], [{"wrapS": 1}])),
        # Materials and cameras as authored.
        "emissive_string": (T, setter(["materials", 0, "emissiveFactor"], "red")),
        "emissive_above_one": (T, setter(["materials", 0, "emissiveFactor"], [2.0, 0.0, 0.0])),
        "emissive_two_values": (T, setter(["materials", 0, "emissiveFactor"], [1.0, 0.0])),
        "emissive_strength_negative": (T, setter(["materials", 0, "extensions",
                                                  "KHR_materials_emissive_strength",
                                                  "emissiveStrength"], -1.0)),
        "emissive_strength_string": (T, setter(["materials", 0, "extensions",
                                                "KHR_materials_emissive_strength",
                                                "emissiveStrength"], "2")),
        "emissive_texture_past": (T, setter(["materials", 0, "emissiveTexture"], {"index": 3})),
        "alpha_mode_unknown": (T, setter(["materials", 0, "alphaMode"], "CUTOUT")),
        "alpha_mode_number": (T, setter(["materials", 0, "alphaMode"], 1)),
        "alpha_cutoff_negative": (T, setter(["materials", 0, "alphaCutoff"], -1.0)),
        "alpha_cutoff_string": (T, setter(["materials", 0, "alphaCutoff"], "0.5")),
        "double_sided_string": (T, setter(["materials", 0, "doubleSided"], "true")),
        "double_sided_number": (T, setter(["materials", 0, "doubleSided"], 1)),
        "ortho_xmag_string": (T, setter(ortho + ["xmag"], "1")),
        "ortho_ymag_string": (T, setter(ortho + ["ymag"], "1")),
        "ortho_xmag_zero": (T, setter(ortho + ["xmag"], 0.0)),
        "ortho_ymag_zero": (T, setter(ortho + ["ymag"], 0.0)),
        "ortho_ymag_negative": (T, setter(ortho + ["ymag"], -1.0)),
        "ortho_znear_negative": (T, setter(ortho + ["znear"], -1.0)),
        "ortho_zfar_zero": (T, setter(ortho + ["zfar"], 0.0)),
        "ortho_zfar_below_znear": (T, setter(ortho, {"xmag": 1.0, "ymag": 1.0, "znear": 2.0,
                                                     "zfar": 1.0})),
        "ortho_zfar_string": (T, setter(ortho + ["zfar"], "10")),
        "ortho_xmag_missing": (T, remover(ortho + ["xmag"])),
        "ortho_missing": (T, remover(ortho)),
        # Empty arrays where the schema asks for at least one element, and repeated extensions.
        "nodes_empty": (M, setter(["nodes"], [])),
        "scenes_empty": (L, setter(["scenes"], [])),
        "scene_nodes_empty": (L, setter(["scenes", 0, "nodes"], [])),
        "children_empty": (L, setter(["nodes", 4, "children"], [])),
        "lights_empty": (unlit_lightless, setter(LIGHTS, [])),
        "materials_empty": (L, setter(["materials"], [])),
        "meshes_empty": (L, setter(["meshes"], [])),
        "primitives_empty": (M, setter(["meshes", 0, "primitives"], [])),
        "accessors_empty": (L, setter(["accessors"], [])),
        "buffer_views_empty": (L, setter(["bufferViews"], [])),
        "buffers_empty": (L, setter(["buffers"], [])),
        "cameras_empty": (M, setter(["cameras"], [])),
        "textures_empty": (M, setter(["textures"], [])),
        "images_empty": (M, setter(["images"], [])),
        "samplers_empty": (M, setter(["samplers"], [])),
        "skins_empty": (M, setter(["skins"], [])),
        "animations_empty": (M, setter(["animations"], [])),
        "extensions_used_empty": (M, setter(["extensionsUsed"], [])),
        "extensions_required_empty": (L, setter(["extensionsRequired"], [])),
        "extensions_used_twice": (L, setter(["extensionsUsed"], ["KHR_lights_punctual",
                                                                 "KHR_lights_punctual"])),
        "extensions_required_twice": (L, setter(["extensionsRequired"],
                                                ["KHR_lights_punctual", "KHR_lights_punctual"])),
        # Indices past their array.
        "light_index_three": (L, setter(["nodes", 1, "extensions", "KHR_lights_punctual",
                                         "light"], 3)),
        "node_mesh_past": (M, setter(["nodes", 0, "mesh"], 4)),
        "scene_past": (L, setter(["scene"], 2)),
        "scene_root_past": (L, setter(["scenes", 0, "nodes"], [0, 9])),
        "child_past": (L, setter(["nodes", 0, "children"], [1, 2, 3, 12])),
        "camera_past": (L, setter(["nodes", 4, "camera"], 3)),
        "material_past": (M, setter(["meshes", 0, "primitives", 0, "material"], 2)),
        "indices_past": (M, setter(["meshes", 0, "primitives", 0, "indices"], 5)),
        "attribute_past": (M, setter(["meshes", 0, "primitives", 0, "attributes", "NORMAL"], 8)),
        "buffer_view_past": (M, setter(["accessors", 1, "bufferView"], 6)),
        "view_past_buffer": (M, setter(["bufferViews", 2, "byteLength"], 60)),
        "buffer_past": (M, setter(["bufferViews", 0, "buffer"], 1)),
        # Required members missing.
        "asset_missing": (L, remover(["asset"])),
        "version_missing": (L, remover(["asset", "version"])),
        "accessor_type_missing": (M, remover(["accessors", 0, "type"])),
        "primitive_attributes_missing": (M, remover(["meshes", 0, "primitives", 0,
                                                     "attributes"])),
        "light_index_missing": (L, remover(["nodes", 1, "extensions", "KHR_lights_punctual",
                                            "light"])),
        # The node tree.
        "node_under_two_parents": (L, setter(["nodes", 4, "children"], [1])),
        "node_twice_in_children": (L, setter(["nodes", 0, "children"], [1, 2, 3, 1])),
        "node_twice_in_scene": (L, setter(["scenes", 0, "nodes"], [0, 4, 4])),
        "root_and_child": (L, setter(["scenes", 0, "nodes"], [0, 1, 4])),
        "node_cycle": (L, setter(["nodes", 1, "children"], [0])),
        "node_cycle_outside_scene": (L, setter(["nodes"], light_document()["nodes"] + [
            {"children": [6]}, {"children": [5]}])),
        # Versions.
        "version_1_0": (L, setter(["asset", "version"], "1.0")),
        "version_3_0": (L, setter(["asset", "version"], "3.0")),
        "version_unparsable": (L, setter(["asset", "version"], "two")),
        "min_version_2_1": (L, setter(["asset", "minVersion"], "2.1")),
        # Required extensions levrt cannot honour (each also in extensionsUsed).
        "required_draco": (M, setter(["extensionsRequired"], ["KHR_draco_mesh_compression"])),
        "required_meshopt": (M, setter(["extensionsRequired"], ["EXT_meshopt_compression"])),
        "required_basisu": (M, setter(["extensionsRequired"], ["KHR_texture_basisu"])),
        "required_unknown": (M, setter(["extensionsRequired"], ["EXT_levrt_unknown"])),
        "required_not_used": (L, setter(["extensionsRequired"], ["KHR_materials_ior"])),
        # What the validator checks in the data and levrt reads its own way.
        "position_min_max_missing": (M, remover(["accessors", 0, "min"])),
        "position_max_wrong": (M, setter(["accessors", 0, "max"], [5.0, 5.0, 5.0])),
        "rotation_not_unit": (L, setter(["nodes", 2, "rotation"], [0.0, 0.0, 0.0, 2.0])),
    }
    for name in ("required_draco", "required_meshopt", "required_basisu", "required_unknown"):
        base, change = mutants[name]
        def used_too(document, change=change):
            change(document)
            document["extensionsUsed"] = document["extensionsUsed"] + document["extensionsRequired"]
        mutants[name] = (base, used_too)
    for name, (base, change) in mutants.items():
        files["bad_" + name + ".gltf"] = edit(base, change)
    files["bad_glb_length_short.glb"] = mesh_glb(length_delta=-4)
    files["bad_glb_length_long.glb"] = mesh_glb(length_delta=8)
    files["bad_glb_version_1.glb"] = mesh_glb(version=1)
    # glTF's JSON is UTF-8 without a byte order mark.
    files["bad_byte_order_mark.gltf"] = b"\xef\xbb\xbf" + json.dumps(L).encode()
    return files


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    out = sys.argv[1]
    os.makedirs(out, exist_ok=True)
    for name, content in cases().items():
        data = content if isinstance(content, bytes) else json.dumps(content, indent=1).encode()
        with open(os.path.join(out, name), "wb") as f:
            f.write(data)


if __name__ == "__main__":
    main()
