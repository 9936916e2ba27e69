#!/usr/bin/env python3
"""Writes a many-light glTF 2.0 street: a long road between two rows of houses (one box mesh,
placed by every house node), a streetlight spot every 4 units on both sides (KHR_lights_punctual,
inner 25 / outer 45 degrees, range 14), a warm point light in front of every house, and a dim
moon (a directional light). Usage: make_gltf_street.py OUT.gltf [SEGMENTS] (lights = 4 x SEGMENTS).
The camera looks down the street from one end. Standard library only."""
import argparse
import base64
import json
import math
import struct


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("out", help="the .gltf file to write")
    parser.add_argument("segments", type=int, nargs="?", default=750,
                        help="street segments of 4 units, 4 lights each (default 750)")
    args = parser.parse_args()
    if args.segments < 1:
        parser.error(f"segments must be at least 1, not {args.segments}")
    out, segments = args.out, args.segments
    length = 4.0 * segments
    # A unit box (y up, base at y = 0) and the road quad: positions, normals, indices.
    box_faces = [((1, 0, 0), (0, 1, 0), (0, 0, 1)), ((-1, 0, 0), (0, 0, 1), (0, 1, 0)),
                 ((0, 1, 0), (0, 0, 1), (1, 0, 0)), ((0, 0, 1), (1, 0, 0), (0, 1, 0)),
                 ((0, 0, -1), (0, 1, 0), (1, 0, 0))]
    positions, normals, indices = [], [], []
    for n, u, v in box_faces:
        base = len(positions)
        for su, sv in ((-1, -1), (1, -1), (1, 1), (-1, 1)):
            p = [0.5 * n[i] + 0.5 * su * u[i] + 0.5 * sv * v[i] for i in range(3)]
            p[1] += 0.5
            positions.append(p)
            normals.append(n)
        indices += [base, base + 1, base + 2, base, base + 2, base + 3]
    road_base = len(positions)
    for x, z in ((-12, 2), (12, 2), (12, -length - 2), (-12, -length - 2)):
        positions.append([x, 0, z])
        normals.append([0, 1, 0])
    road_indices = [road_base, road_base + 1, road_base + 2, road_base, road_base + 2, road_base + 3]
    blob = b"".join(struct.pack("<3f", *p) for p in positions)
    blob += b"".join(struct.pack("<3f", *n) for n in normals)
    blob += b"".join(struct.pack("<I", i) for i in indices + road_indices)
    vertex_bytes = 12 * len(positions)
    views = [{"buffer": 0, "byteOffset": 0, "byteLength": vertex_bytes},
             {"buffer": 0, "byteOffset": vertex_bytes, "byteLength": vertex_bytes},
             {"buffer": 0, "byteOffset": 2 * vertex_bytes, "byteLength": 4 * len(indices)},
             {"buffer": 0, "byteOffset": 2 * vertex_bytes + 4 * len(indices), "byteLength": 4 * len(road_indices)}]
    accessors = [{"bufferView": 0, "componentType": 5126, "type": "VEC3", "count": len(positions),
                  "min": [-12, 0, -length - 2], "max": [12, 1, 2]},
                 {"bufferView": 1, "componentType": 5126, "type": "VEC3", "count": len(positions)},
                 {"bufferView": 2, "componentType": 5125, "type": "SCALAR", "count": len(indices)},
                 {"bufferView": 3, "componentType": 5125, "type": "SCALAR", "count": len(road_indices)}]
    lights = [
        {"type": "spot", "color": [1.0, 0.85, 0.6], "intensity": 400, "range": 14,
         "spot": {"innerConeAngle": math.radians(25), "outerConeAngle": math.radians(45)}},
        {"type": "point", "color": [1.0, 0.55, 0.25], "intensity": 60, "range": 10},
        {"type": "directional", "color": [0.6, 0.7, 1.0], "intensity": 1.0},
    ]
    down = [-math.sqrt(0.5), 0, 0, math.sqrt(0.5)]  # -Z turned onto -Y
    nodes = [{"mesh": 1, "name": "road"}]
    for k in range(segments):
        z = -4.0 * k
        for side in (-1, 1):
            nodes.append({"translation": [side * 6.0, 6.0, z], "rotation": down,
                          "extensions": {"KHR_lights_punctual": {"light": 0}}})
            nodes.append({"translation": [side * 8.5, 1.5, z - 2.0],
                          "extensions": {"KHR_lights_punctual": {"light": 1}}})
            nodes.append({"mesh": 0, "translation": [side * 11.0, 0, z - 2.0], "scale": [3.0, 5.0 + (k % 3), 3.0]})
    nodes.append({"rotation": [-0.3, 0.2, 0.1, 0.93], "extensions": {"KHR_lights_punctual": {"light": 2}}})
    nodes.append({"camera": 0, "translation": [0, 4, 6], "rotation": [-0.06, 0, 0, 0.998]})
    gltf = {
        "asset": {"version": "2.0", "generator": "levrt tools/make_gltf_street.py"},
        "extensionsUsed": ["KHR_lights_punctual"],
        "extensions": {"KHR_lights_punctual": {"lights": lights}},
        "buffers": [{"byteLength": len(blob),
                     "uri": "data:application/octet-stream;base64," + base64.b64encode(blob).decode()}],
        "bufferViews": views, "accessors": accessors,
        "materials": [{"pbrMetallicRoughness": {"baseColorFactor": [0.8, 0.75, 0.7, 1], "metallicFactor": 0}},
                      {"pbrMetallicRoughness": {"baseColorFactor": [0.5, 0.5, 0.55, 1], "metallicFactor": 0,
                                                "roughnessFactor": 0.6}}],
        "meshes": [{"name": "house", "primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1}, "indices": 2, "material": 0}]},
                   {"name": "road", "primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1}, "indices": 3, "material": 1}]}],
        "cameras": [{"type": "perspective", "perspective": {"yfov": 0.8, "znear": 0.1}}],
        "scenes": [{"nodes": list(range(len(nodes)))}], "scene": 0, "nodes": nodes,
    }
    with open(out, "w") as f:
        json.dump(gltf, f)


if __name__ == "__main__":
    main()
