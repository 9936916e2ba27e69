#!/usr/bin/env python3
"""Writes the glTF fuzzer's seed corpus into OUT_DIR: a small street (tools/make_gltf_street.py,
self-contained: its buffer is a data URI) as .gltf, and the same scene packed as .glb; then one
seed per hostile class of docs/extremes.md (glTF files), each near a limit, so that mutations
cross it: deep JSON nesting, a deep node chain, URIs leading out of the folder (.., percent-
encoded, absolute, file://, '.'), huge counts (a zero accessor of millions of vertices, one
reused by many primitives), wrapping and negative indices, and GLB chunk layouts (no BIN chunk,
a short BIN chunk, a chunk length past the end). Each seed starts with the byte that
gltf_scene_fuzz.cpp reads as the format (even: .gltf, odd: .glb). The dictionary beside this
script (gltf.dict) gives the fuzzer glTF's keys and these values. Usage: gltf_seeds.py OUT_DIR.
Standard library only."""
import base64
import json
import os
import struct
import subprocess
import sys
import tempfile


def pack_glb(document):
    """A .glb of the document with its data-URI buffer moved into the binary chunk."""
    buffer = document["buffers"][0]
    blob = base64.b64decode(buffer.pop("uri").split(",", 1)[1])
    blob += b"\0" * (-len(blob) % 4)
    buffer["byteLength"] = len(blob)
    text = json.dumps(document, separators=(",", ":")).encode()
    text += b" " * (-len(text) % 4)
    body = struct.pack("<II", len(text), 0x4E4F534A) + text + struct.pack("<II", len(blob), 0x004E4942) + blob
    return struct.pack("<III", 0x46546C67, 2, 12 + len(body)) + body


TRIANGLE = "data:application/octet-stream;base64," + base64.b64encode(
    struct.pack("<9f", 0, 0, 0, 1, 0, 0, 0, 1, 0)).decode()


def document(**parts):
    """A glTF drawing mesh 0 from node 0 unless `parts` say otherwise."""
    doc = {"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}],
           "buffers": [{"byteLength": 36, "uri": TRIANGLE}],
           "bufferViews": [{"buffer": 0, "byteLength": 36}],
           "accessors": [{"bufferView": 0, "componentType": 5126, "type": "VEC3", "count": 3}],
           "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
           "nodes": [{"mesh": 0}]}
    doc.update(parts)
    return doc


def glb(text, blob, json_length=None, total_delta=0):
    """A .glb of JSON `text` and BIN `blob` (None: no BIN chunk), lengths overridable."""
    text += b" " * (-len(text) % 4)
    body = struct.pack("<II", len(text) if json_length is None else json_length, 0x4E4F534A) + text
    if blob is not None:
        body += struct.pack("<II", len(blob), 0x004E4942) + blob
    return struct.pack("<III", 0x46546C67, 2, 12 + len(body) + total_delta) + body


def hostile_seeds():
    """(name, bytes with the format byte in front) for every hostile class."""
    dump = lambda doc: json.dumps(doc, separators=(",", ":")).encode()
    seeds = {}
    seeds["deep_extras.gltf"] = dump(document(extras=0)).replace(
        b'"extras":0', b'"extras":' + b"[" * 250 + b"]" * 250)
    chain = [{"children": [i + 1], "translation": [0, 1, 0]} for i in range(299)] + [{"mesh": 0}]
    seeds["deep_nodes.gltf"] = dump(document(nodes=chain))
    for name, uri in (("dotdot", "../x.bin"), ("encoded", "%2e%2e/x.bin"), ("absolute", "/etc/x"),
                      ("file", "file:///etc/x"), ("dot", "."), ("nul", "a%00.bin"),
                      ("image", "../x.png")):
        if name == "image":
            doc = document(images=[{"uri": uri}], textures=[{"source": 0}],
                           materials=[{"pbrMetallicRoughness": {"baseColorTexture": {"index": 0}}}])
            doc["meshes"][0]["primitives"][0]["material"] = 0
        else:
            doc = document(buffers=[{"byteLength": 36, "uri": uri}])
        seeds["uri_" + name + ".gltf"] = dump(doc)
    zeros = [{"componentType": 5126, "type": "VEC3", "count": 3000000}]
    seeds["huge_accessor.gltf"] = dump(document(accessors=[dict(zeros[0], count=30000000)]))
    seeds["reused_accessor.gltf"] = dump(document(
        accessors=zeros, meshes=[{"primitives": [{"attributes": {"POSITION": 0}}] * 40}]))
    lamp = {"KHR_lights_punctual": {"lights": [{"type": "point"}]}}
    seeds["wrapping_light.gltf"] = dump(document(
        extensions=lamp, nodes=[{"extensions": {"KHR_lights_punctual": {"light": 4294967296}}}]))
    seeds["negative.gltf"] = dump(document(
        scene=-2, bufferViews=[{"buffer": 0, "byteOffset": -4, "byteLength": 36}],
        meshes=[{"primitives": [{"attributes": {"POSITION": 0}, "mode": -1}]}]))
    seeds["trailing.gltf"] = dump(document()) + b"\0garbage"
    plain = dump(document(buffers=[{"byteLength": 36}]))
    blob = struct.pack("<9f", 0, 0, 0, 1, 0, 0, 0, 1, 0)
    seeds["no_bin.glb"] = glb(plain, None)
    seeds["short_bin.glb"] = glb(plain, blob[:20])
    seeds["json_past_end.glb"] = glb(plain, blob, json_length=1 << 30)
    seeds["total_past_end.glb"] = glb(plain, blob, total_delta=64)
    return [(name, (b"\1" if name.endswith(".glb") else b"\0") + data)
            for name, data in seeds.items()]


def main():
    out_dir = sys.argv[1]
    here = os.path.dirname(os.path.abspath(__file__))
    street = os.path.join(here, "..", "..", "tools", "make_gltf_street.py")
    with tempfile.TemporaryDirectory() as scratch:
        path = os.path.join(scratch, "street.gltf")
        subprocess.run([sys.executable, street, path, "2"], check=True)
        with open(path, "rb") as f:
            text = f.read()
    with open(os.path.join(out_dir, "street.gltf.seed"), "wb") as f:
        f.write(b"\0" + text)
    with open(os.path.join(out_dir, "street.glb.seed"), "wb") as f:
        f.write(b"\1" + pack_glb(json.loads(text)))
    for name, data in hostile_seeds():
        with open(os.path.join(out_dir, name + ".seed"), "wb") as f:
            f.write(data)


if __name__ == "__main__":
    main()
