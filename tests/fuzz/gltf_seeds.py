#!/usr/bin/env python3
"""Writes the glTF fuzzer's seed corpus into OUT_DIR: a small street (tools/make_gltf_street.py,
self-contained: its buffer is a data URI) as .gltf, and the same scene packed as .glb. Each seed
starts with the byte that gltf_scene_fuzz.cpp reads as the format (even: .gltf, odd: .glb), so the
fuzzer begins from inputs that reach the geometry, light and material readers rather than from
bytes that fail JSON parsing. Usage: gltf_seeds.py OUT_DIR. Standard library only."""
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


if __name__ == "__main__":
    main()
