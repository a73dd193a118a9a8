#!/usr/bin/env python3
"""A city block as glTF: a grid of box buildings of seeded random footprints and heights on a
ground plane, streets between them, and the file's own camera at street level looking down a
street - a close-up view of a large scene, where a radius set from the scene's diagonal is far
larger than what the view spans. Units: metres (a block 20 m, streets 8 m, buildings 6-40 m tall).
One self-contained .gltf (the buffer embedded as a data: URI).

Usage: city_gltf.py OUT.gltf [--blocks N] [--seed S]"""
import argparse
import base64
import json
import random
import struct


def box(x0, z0, x1, z1, h):
    """Positions, normals and indices of a closed box from y = 0 to y = h (outward faces, CCW)."""
    p, n, i = [], [], []
    faces = [  # (normal, four corners counter-clockwise seen from outside)
        ((0, 1, 0), [(x0, h, z0), (x0, h, z1), (x1, h, z1), (x1, h, z0)]),
        ((0, -1, 0), [(x0, 0, z0), (x1, 0, z0), (x1, 0, z1), (x0, 0, z1)]),
        ((1, 0, 0), [(x1, 0, z0), (x1, h, z0), (x1, h, z1), (x1, 0, z1)]),
        ((-1, 0, 0), [(x0, 0, z0), (x0, 0, z1), (x0, h, z1), (x0, h, z0)]),
        ((0, 0, 1), [(x0, 0, z1), (x1, 0, z1), (x1, h, z1), (x0, h, z1)]),
        ((0, 0, -1), [(x0, 0, z0), (x0, h, z0), (x1, h, z0), (x1, 0, z0)]),
    ]
    for normal, quad in faces:
        base = len(p)
        p += quad
        n += [normal] * 4
        i += [base, base + 1, base + 2, base, base + 2, base + 3]
    return p, n, i


def city(blocks, seed):
    rng = random.Random(seed)
    block, street = 20.0, 8.0
    size = blocks * (block + street) + street
    pos, nor, idx = [], [], []

    def add(part):
        p, n, i = part
        base = len(pos)
        pos.extend(p)
        nor.extend(n)
        idx.extend(base + k for k in i)

    # The ground: one quad facing up.
    add(([(0, 0, 0), (0, 0, size), (size, 0, size), (size, 0, 0)], [(0, 1, 0)] * 4, [0, 1, 2, 0, 2, 3]))
    for bx in range(blocks):
        for bz in range(blocks):
            x0, z0 = street + bx * (block + street), street + bz * (block + street)
            for sx in range(2):  # four buildings a block, with gaps between them
                for sz in range(2):
                    w, d = rng.uniform(6, 9.5), rng.uniform(6, 9.5)
                    ox, oz = x0 + sx * 10 + rng.uniform(0, 10 - w), z0 + sz * 10 + rng.uniform(0, 10 - d)
                    add(box(ox, oz, ox + w, oz + d, rng.uniform(6, 40)))
    # Street level, 1.7 m up, in the middle of an inner street, looking along it toward the far end.
    eye_x = (blocks // 2) * (block + street) + street / 2
    eye = (eye_x, 1.7, street + 2)
    return pos, nor, idx, eye, size


def gltf(pos, nor, idx, eye, size):
    data = b"".join(struct.pack("<3f", *v) for v in pos) + b"".join(struct.pack("<3f", *v) for v in nor)
    data += b"".join(struct.pack("<I", k) for k in idx)
    npos = len(pos)
    lo = [min(v[a] for v in pos) for a in range(3)]
    hi = [max(v[a] for v in pos) for a in range(3)]
    # The camera looks down -z of its node: turn it to look along +z (down the street).
    return {
        "asset": {"version": "2.0", "generator": "ssaolab tools/city_gltf.py"},
        "scene": 0,
        "scenes": [{"nodes": [0, 1]}],
        "nodes": [{"mesh": 0, "name": "city"},
                  {"camera": 0, "name": "street", "translation": list(eye), "rotation": [0, 1, 0, 0]}],
        "cameras": [{"type": "perspective", "perspective": {"yfov": 1.0, "znear": 0.1, "zfar": size * 2,
                                                              "aspectRatio": 16 / 9}}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1}, "indices": 2, "material": 0}]}],
        "materials": [{"pbrMetallicRoughness": {"baseColorFactor": [0.8, 0.8, 0.8, 1], "metallicFactor": 0}}],
        "buffers": [{"byteLength": len(data),
                     "uri": "data:application/octet-stream;base64," + base64.b64encode(data).decode()}],
        "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 12 * npos, "target": 34962},
                        {"buffer": 0, "byteOffset": 12 * npos, "byteLength": 12 * npos, "target": 34962},
                        {"buffer": 0, "byteOffset": 24 * npos, "byteLength": 4 * len(idx), "target": 34963}],
        "accessors": [{"bufferView": 0, "componentType": 5126, "count": npos, "type": "VEC3", "min": lo, "max": hi},
                      {"bufferView": 1, "componentType": 5126, "count": npos, "type": "VEC3"},
                      {"bufferView": 2, "componentType": 5125, "count": len(idx), "type": "SCALAR"}],
    }


def main():
    ap = argparse.ArgumentParser(prog="city_gltf", description=__doc__.split("\n")[0])
    ap.add_argument("out")
    ap.add_argument("--blocks", type=int, default=8)
    ap.add_argument("--seed", type=int, default=7)
    a = ap.parse_args()
    if not 1 <= a.blocks <= 64:
        ap.error("--blocks must be in [1, 64]")
    with open(a.out, "w", encoding="utf-8") as f:
        json.dump(gltf(*city(a.blocks, a.seed)), f)


if __name__ == "__main__":
    main()
