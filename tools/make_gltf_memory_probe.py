#!/usr/bin/env python3
"""Writes the glTF files that measure the reader's memory budget (scenes/gltf_budget.h,
docs/extremes.md "glTF memory budget"): peak RSS of `levrt render` on them, against the size,
gives the bytes per vertex, triangle and texel.

  make_gltf_memory_probe.py OUT.gltf grid N [flat]   an N x N grid of quads, (N+1)^2 vertices and
                                                     2 N^2 triangles in OUT.gltf.bin, with normals
                                                     (or flat: none, so every triangle gets three)
  make_gltf_memory_probe.py OUT.gltf texture W [USES]  a triangle sampling a W x W grey PNG of
                                                     zeros (OUT.gltf.png), through USES textures

Both hold one point light. Standard library only."""
import array
import base64
import argparse
import json
import struct
import zlib


def grid(out, n, flat):
    positions, normals, indices = array.array("f"), array.array("f"), array.array("I")
    for j in range(n + 1):
        for i in range(n + 1):
            positions.extend((i / n, j / n, 0.0))
            normals.extend((0.0, 0.0, 1.0))
    for j in range(n):
        for i in range(n):
            a = j * (n + 1) + i
            indices.extend((a, a + 1, a + n + 2, a, a + n + 2, a + n + 1))
    p, q, r = positions.tobytes(), normals.tobytes(), indices.tobytes()
    with open(out + ".bin", "wb") as f:
        f.write(p + q + r)
    attributes = {"POSITION": 0} if flat else {"POSITION": 0, "NORMAL": 1}
    return {
        "buffers": [{"byteLength": len(p) + len(q) + len(r), "uri": out.split("/")[-1] + ".bin"}],
        "bufferViews": [{"buffer": 0, "byteLength": len(p)},
                        {"buffer": 0, "byteOffset": len(p), "byteLength": len(q)},
                        {"buffer": 0, "byteOffset": len(p) + len(q), "byteLength": len(r)}],
        "accessors": [{"bufferView": 0, "componentType": 5126, "type": "VEC3",
                       "count": (n + 1) ** 2},
                      {"bufferView": 1, "componentType": 5126, "type": "VEC3",
                       "count": (n + 1) ** 2},
                      {"bufferView": 2, "componentType": 5125, "type": "SCALAR",
                       "count": 6 * n * n}],
        "meshes": [{"primitives": [{"attributes": attributes, "indices": 2}]}]}


def texture(out, width, uses):
    def chunk(kind, data):
        return (struct.pack(">I", len(data)) + kind + data +
                struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF))
    rows = (b"\0" * (width + 1)) * width  # filter byte 0, then the row
    png = (b"\x89PNG\r\n\x1a\n" +
           chunk(b"IHDR", struct.pack(">IIBBBBB", width, width, 8, 0, 0, 0, 0)) +
           chunk(b"IDAT", zlib.compress(rows, 9)) + chunk(b"IEND", b""))
    with open(out + ".png", "wb") as f:
        f.write(png)
    blob = struct.pack("<9f", 0, 0, 0, 1, 0, 0, 0, 1, 0) + struct.pack("<6f", 0, 0, 1, 0, 0, 1)
    return {
        "buffers": [{"byteLength": len(blob),
                     "uri": "data:application/octet-stream;base64," +
                            base64.b64encode(blob).decode()}],
        "bufferViews": [{"buffer": 0, "byteLength": 36},
                        {"buffer": 0, "byteOffset": 36, "byteLength": 24}],
        "accessors": [{"bufferView": 0, "componentType": 5126, "type": "VEC3", "count": 3},
                      {"bufferView": 1, "componentType": 5126, "type": "VEC2", "count": 3}],
        "images": [{"uri": out.split("/")[-1] + ".png"}],
        "textures": [{"source": 0}] * uses,
        "materials": [{"pbrMetallicRoughness": {"baseColorTexture": {"index": i}}}
                      for i in range(uses)],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "TEXCOORD_0": 1}, "material": i}
                                   for i in range(uses)]}]}


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("out", help="the .gltf file to write")
    parser.add_argument("kind", choices=["grid", "texture"])
    parser.add_argument("size", type=int, help="quads a side (grid) or texels a side (texture)")
    parser.add_argument("extra", nargs="?", default=None,
                        help="grid: 'flat' for no normals; texture: how many textures use it")
    args = parser.parse_args()
    out, kind, size = args.out, args.kind, args.size
    if kind == "grid":
        document = grid(out, size, args.extra == "flat")
    else:
        document = texture(out, size, int(args.extra) if args.extra else 1)
    document.update({
        "asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0, 1]}],
        "extensions": {"KHR_lights_punctual": {"lights": [{"type": "point", "intensity": 10}]}},
        "nodes": [{"mesh": 0}, {"translation": [0.5, 0.5, 1],
                                "extensions": {"KHR_lights_punctual": {"light": 0}}}]})
    with open(out, "w") as f:
        json.dump(document, f)


if __name__ == "__main__":
    main()
