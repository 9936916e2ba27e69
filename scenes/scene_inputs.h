// The files reading a scene opens: the scene file itself and, for glTF, the external buffers and
// images its URIs name. Commands list them before any work so that no output replaces an input
// (app/output_files.h). The list errs on the side of more: each relative URI is resolved in the
// glTF's folder both as written and decoded as tinygltf decodes it (percent escapes, '+' as a
// space), and each with its `..` resolved lexically, as the reader resolves it. It never fails: a
// file it cannot read or parse yields what it found so far, and the scene's reader reports the
// problem. It reads only a regular file of at most kMaxSceneFileBytes (of a larger binary glTF, its
// header and a JSON chunk within that) and parses it without building a document (one SAX pass), so
// a hostile file costs no more than its size.
#pragma once

#include <string>
#include <vector>

namespace scenes {

// `path` is what --scene names: a model name lists nothing, any scene file lists itself first.
std::vector<std::string> scene_input_files(const std::string& path);

}  // namespace scenes
