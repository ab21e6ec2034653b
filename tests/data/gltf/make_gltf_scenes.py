#!/usr/bin/env python3
"""Writes the glTF scenes the tests load (run from this folder; the outputs are committed):

  node-tree.gltf (+ node-tree-external.gltf, node-tree.bin): a chrome cube three nodes deep (TRS,
      quaternion, matrix), a red quad, a camera and a directional KHR_lights_punctual light;
      the buffer embedded as a data: URI, and the same scene with it in an external file.
  chrome-sphere.glb: a closed chrome UV sphere (metallic 1, roughness 0.05) on a floor with a
      checker texture (a PNG in the GLB's buffer, repeated 6 times a side), a red box and a green
      box, a camera looking at it.
  textured-box.gltf (+ crate.png): a box whose six faces each show the whole of an external PNG
      (clamped), on a floor tinted by the same image, mirrored-repeat; no camera, no lights.
"""
import base64, json, math, struct, zlib


def pack(floats=(), ints=()):
    return struct.pack("<%df" % len(floats), *floats) + struct.pack("<%dI" % len(ints), *ints)


class Builder:
    def __init__(self):
        self.bin = b""
        self.doc = {"asset": {"version": "2.0", "generator": "specula tests/data/gltf/make_gltf_scenes.py"},
                    "buffers": [], "bufferViews": [], "accessors": [], "meshes": [], "materials": [],
                    "nodes": [], "scenes": [], "scene": 0}

    def accessor(self, data, kind, count, component, minmax=None):
        while len(self.bin) % 4:
            self.bin += b"\0"
        view = {"buffer": 0, "byteOffset": len(self.bin), "byteLength": len(data)}
        self.bin += data
        self.doc["bufferViews"].append(view)
        acc = {"bufferView": len(self.doc["bufferViews"]) - 1, "componentType": component, "count": count, "type": kind}
        if minmax:
            acc["min"], acc["max"] = minmax
        self.doc["accessors"].append(acc)
        return len(self.doc["accessors"]) - 1

    def mesh(self, name, positions, normals, indices, material, uvs=None):
        flat = [c for p in positions for c in p]
        lo = [min(p[i] for p in positions) for i in range(3)]
        hi = [max(p[i] for p in positions) for i in range(3)]
        pos = self.accessor(pack(flat), "VEC3", len(positions), 5126, (lo, hi))
        nor = self.accessor(pack([c for n in normals for c in n]), "VEC3", len(normals), 5126)
        ind = self.accessor(pack(ints=indices), "SCALAR", len(indices), 5125)
        attributes = {"POSITION": pos, "NORMAL": nor}
        if uvs:
            attributes["TEXCOORD_0"] = self.accessor(pack([c for uv in uvs for c in uv]), "VEC2", len(uvs), 5126)
        self.doc["meshes"].append({"name": name, "primitives": [
            {"attributes": attributes, "indices": ind, "material": material}]})
        return len(self.doc["meshes"]) - 1

    def material(self, name, rgb, metallic, roughness, texture=None):
        pbr = {"baseColorFactor": list(rgb) + [1.0], "metallicFactor": metallic, "roughnessFactor": roughness}
        if texture is not None:
            pbr["baseColorTexture"] = {"index": texture}
        self.doc["materials"].append({"name": name, "pbrMetallicRoughness": pbr})
        return len(self.doc["materials"]) - 1

    def texture(self, image, wrap):
        """A texture of image `image` (an index) with a sampler wrapping both ways by `wrap` (GL's enum)."""
        self.doc.setdefault("samplers", []).append({"wrapS": wrap, "wrapT": wrap})
        self.doc.setdefault("textures", []).append({"source": image, "sampler": len(self.doc["samplers"]) - 1})
        return len(self.doc["textures"]) - 1

    def embedded_image(self, png):
        """An image stored in the binary buffer (GLB)."""
        while len(self.bin) % 4:
            self.bin += b"\0"
        self.doc["bufferViews"].append({"buffer": 0, "byteOffset": len(self.bin), "byteLength": len(png)})
        self.bin += png
        self.doc.setdefault("images", []).append({"bufferView": len(self.doc["bufferViews"]) - 1, "mimeType": "image/png"})
        return len(self.doc["images"]) - 1

    def node(self, **fields):
        self.doc["nodes"].append(fields)
        return len(self.doc["nodes"]) - 1

    def finish(self):
        while len(self.bin) % 4:
            self.bin += b"\0"
        self.doc["buffers"] = [{"byteLength": len(self.bin)}]


REPEAT, CLAMP, MIRRORED_REPEAT = 10497, 33071, 33648


def png(width, height, pixel):
    """An RGB PNG whose texel (x, y), row 0 at the top, is pixel(x, y) = (r, g, b) bytes."""
    rows = b"".join(b"\0" + bytes(c for x in range(width) for c in pixel(x, y)) for y in range(height))
    chunk = lambda kind, data: struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data))
    header = struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0)
    return b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header) + chunk(b"IDAT", zlib.compress(rows, 9)) + chunk(b"IEND", b"")


def checker_png():
    """64 x 64 texels, 8 x 8 cells of warm white and slate blue."""
    return png(64, 64, lambda x, y: (235, 225, 200) if (x // 8 + y // 8) % 2 == 0 else (40, 60, 110))


def crate_png():
    """32 x 32 texels: an orange frame around a quartered centre (red, green / blue, yellow), so
    a face's orientation shows."""
    def pixel(x, y):
        if min(x, y, 31 - x, 31 - y) < 4:
            return (220, 130, 30)
        return [[(200, 40, 40), (40, 170, 60)], [(40, 70, 200), (230, 210, 40)]][y // 16][x // 16]
    return png(32, 32, pixel)


def box(half):
    """A closed box: 24 vertices (flat normals), 12 triangles, fronts outwards; uv covers each face once."""
    positions, normals, indices = [], [], []
    for axis in range(3):
        for sign in (-1.0, 1.0):
            u, v = (axis + 1) % 3, (axis + 2) % 3
            corners = []
            for a, b in ((-1, -1), (1, -1), (1, 1), (-1, 1)):
                p = [0.0, 0.0, 0.0]
                p[axis], p[u], p[v] = sign * half[axis], a * half[u], b * half[v]
                corners.append(p)
            n = [0.0, 0.0, 0.0]
            n[axis] = sign
            base = len(positions)
            positions += corners
            normals += [n] * 4
            quad = [0, 1, 2, 0, 2, 3] if sign > 0 else [0, 2, 1, 0, 3, 2]
            indices += [base + i for i in quad]
    return positions, normals, indices


def box_uvs():
    return [[0, 1], [1, 1], [1, 0], [0, 0]] * 6


def sphere(radius, rings, segments):
    """A closed UV sphere with shared seam and pole vertices, fronts outwards."""
    positions, normals = [[0.0, radius, 0.0]], [[0.0, 1.0, 0.0]]
    for r in range(1, rings):
        theta = math.pi * r / rings
        for s in range(segments):
            phi = 2.0 * math.pi * s / segments
            n = [math.sin(theta) * math.cos(phi), math.cos(theta), -math.sin(theta) * math.sin(phi)]
            positions.append([radius * c for c in n])
            normals.append(n)
    positions.append([0.0, -radius, 0.0])
    normals.append([0.0, -1.0, 0.0])
    south = len(positions) - 1
    at = lambda r, s: 1 + (r - 1) * segments + s % segments
    indices = []
    for s in range(segments):
        indices += [0, at(1, s), at(1, s + 1)]
        indices += [south, at(rings - 1, s + 1), at(rings - 1, s)]
    for r in range(1, rings - 1):
        for s in range(segments):
            a, b, c, d = at(r, s), at(r, s + 1), at(r + 1, s), at(r + 1, s + 1)
            indices += [a, c, d, a, d, b]
    return positions, normals, indices


def quad(half):
    return ([[-half, 0, -half], [half, 0, -half], [half, 0, half], [-half, 0, half]],
            [[0, 1, 0]] * 4, [0, 2, 1, 0, 3, 2])


def quad_uvs(repeats):
    return [[0, 0], [repeats, 0], [repeats, repeats], [0, repeats]]


def node_tree():
    g = Builder()
    chrome = g.material("chrome", (0.9, 0.9, 0.9), 1.0, 0.05)
    red = g.material("red", (0.8, 0.1, 0.1), 0.0, 0.6)
    cube = g.mesh("cube", *box((0.5, 0.5, 0.5)), chrome)
    floor = g.mesh("quad", *quad(4.0), red)
    s = math.sqrt(0.5)
    grandchild = g.node(name="cube", mesh=cube, matrix=[1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 3, 1])
    child = g.node(name="child", translation=[0, 1, 0], scale=[2, 2, 2], children=[grandchild])
    root = g.node(name="root", translation=[1, 0, 0], rotation=[0, s, 0, s], children=[child])
    ground = g.node(name="ground", mesh=floor, translation=[0, -1, 0])
    g.doc["cameras"] = [{"type": "perspective", "perspective": {"yfov": 0.7, "znear": 0.1, "aspectRatio": 1.333}}]
    camera = g.node(name="camera", camera=0, translation=[7, 3, 12])
    g.doc["extensionsUsed"] = ["KHR_lights_punctual"]
    g.doc["extensions"] = {"KHR_lights_punctual": {"lights": [{"type": "directional", "intensity": 3.0}]}}
    sun = g.node(name="sun", rotation=[-0.3826834, 0, 0, 0.9238795], extensions={"KHR_lights_punctual": {"light": 0}})
    g.doc["scenes"] = [{"nodes": [root, ground, camera, sun]}]
    g.finish()
    embedded = dict(g.doc)
    embedded["buffers"] = [{"byteLength": len(g.bin),
                            "uri": "data:application/octet-stream;base64," + base64.b64encode(g.bin).decode()}]
    with open("node-tree.gltf", "w") as f:
        json.dump(embedded, f, indent=1)
    external = dict(g.doc)
    external["buffers"] = [{"byteLength": len(g.bin), "uri": "node-tree.bin"}]
    with open("node-tree-external.gltf", "w") as f:
        json.dump(external, f, indent=1)
    with open("node-tree.bin", "wb") as f:
        f.write(g.bin)


def chrome_sphere():
    g = Builder()
    chrome = g.material("chrome", (1.0, 1.0, 1.0), 1.0, 0.05)
    grey = g.material("floor", (0.9, 0.9, 0.9), 0.0, 0.8, texture=g.texture(g.embedded_image(checker_png()), REPEAT))
    red = g.material("red", (0.8, 0.08, 0.05), 0.0, 0.5)
    green = g.material("green", (0.1, 0.6, 0.15), 0.0, 0.5)
    ball = g.mesh("sphere", *sphere(1.0, 48, 96), chrome)
    floor = g.mesh("floor", *quad(6.0), grey, uvs=quad_uvs(6))
    red_box = g.mesh("red box", *box((0.6, 0.6, 0.6)), red)
    green_box = g.mesh("green box", *box((0.4, 0.9, 0.4)), green)
    nodes = [g.node(name="sphere", mesh=ball, translation=[0, 1, 0]),
             g.node(name="floor", mesh=floor),
             g.node(name="red box", mesh=red_box, translation=[2.2, 0.6, 0.8]),
             g.node(name="green box", mesh=green_box, translation=[-1.8, 0.9, 1.5])]
    g.doc["cameras"] = [{"type": "perspective", "perspective": {"yfov": 0.75, "znear": 0.1}}]
    # Looks from (0, 2.5, 6) down at the sphere: a rotation of -0.25 rad about x.
    nodes.append(g.node(name="camera", camera=0, translation=[0, 2.5, 6], rotation=[-0.1243503, 0, 0, 0.9922385]))
    g.doc["scenes"] = [{"nodes": nodes}]
    g.finish()
    text = json.dumps(g.doc).encode()
    text += b" " * (-len(text) % 4)
    length = 12 + 8 + len(text) + 8 + len(g.bin)
    with open("chrome-sphere.glb", "wb") as f:
        f.write(b"glTF" + struct.pack("<II", 2, length) + struct.pack("<I", len(text)) + b"JSON" + text)
        f.write(struct.pack("<I", len(g.bin)) + b"BIN\0" + g.bin)


def textured_box():
    g = Builder()
    g.doc["images"] = [{"uri": "crate.png"}]
    crate = g.material("crate", (1.0, 1.0, 1.0), 0.0, 0.7, texture=g.texture(0, CLAMP))
    tinted = g.material("tinted floor", (0.6, 0.6, 0.6), 0.0, 0.9, texture=g.texture(0, MIRRORED_REPEAT))
    cube = g.mesh("crate", *box((0.5, 0.5, 0.5)), crate, uvs=box_uvs())
    floor = g.mesh("floor", *quad(3.0), tinted, uvs=quad_uvs(3))
    g.doc["scenes"] = [{"nodes": [g.node(name="crate", mesh=cube, translation=[0, 0.5, 0], rotation=[0, 0.3826834, 0, 0.9238795]),
                                  g.node(name="floor", mesh=floor)]}]
    g.finish()
    g.doc["buffers"] = [{"byteLength": len(g.bin),
                         "uri": "data:application/octet-stream;base64," + base64.b64encode(g.bin).decode()}]
    with open("textured-box.gltf", "w") as f:
        json.dump(g.doc, f, indent=1)
    with open("crate.png", "wb") as f:
        f.write(crate_png())


if __name__ == "__main__":
    node_tree()
    chrome_sphere()
    textured_box()
