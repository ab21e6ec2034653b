#pragma once
// What makes a scene file's object a mirror, and which materials of an included glTF file are mirrors.
#include "scene/GltfImporter.h"
#include "scene/JsonNode.h"
#include "scene/MirrorInfo.h"
#include "scene/NameIndex.h"

namespace specula::scene::file {

// An object's "mirror": curvature, open or closed (an open one names its closed twin among `meshes`),
// and an analytic quadric or an extrusion the mirror exactly is.
MirrorInfo readMirror(const JsonNode& node, const NameIndex& meshes);

// An include's "mirror_rule": {"metallic": at least, "roughness": at most, "materials": {"name": true | false}}.
GltfMirrorRule readMirrorRule(const JsonNode& node);

}  // namespace specula::scene::file
