#!/usr/bin/env python3
"""check_includes.py on small made-up trees: it names the includes the tables forbid, and only those."""
import pathlib
import sys
import tempfile
import unittest

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
import check_includes  # noqa: E402

PAGE = """
<!-- layers:begin -->
| folder | may include |
|---|---|
| server/base | — |
| server/gl | server/base |
| server/scene | server/base |
| proto | server/base |
<!-- layers:end -->
<!-- layer-exceptions:begin -->
| files | may also include | why |
|---|---|---|
| server/gl/Upload.* | server/scene/Mesh.h | a reason |
<!-- layer-exceptions:end -->
"""


class CheckIncludesTest(unittest.TestCase):
    def problems(self, files):
        with tempfile.TemporaryDirectory() as directory:
            root = pathlib.Path(directory)
            files = {"docs/layers.md": PAGE, "server/base/Result.h": "", "server/scene/Mesh.h": "",
                     "server/gl/Upload.cpp": "", "proto/specula.proto": "", **files}
            for path, text in files.items():
                (root / path).parent.mkdir(parents=True, exist_ok=True)
                (root / path).write_text(text)
            return list(check_includes.problems(root))

    def test_allowed_includes_pass(self):
        self.assertEqual(self.problems({
            "server/gl/Context.h": '#include "base/Result.h"\n#include "Local.h"\n',
            "server/gl/Local.h": "",
            "proto/Codec.h": '#include "specula.pb.h"\n#include "base/Result.h"\n',
        }), [])

    def test_a_crossing_is_named_by_file_and_line(self):
        found = self.problems({"server/gl/Meshes.h": '// comment\n#include "scene/Mesh.h"\n'})
        self.assertEqual(len(found), 1)
        self.assertTrue(found[0].startswith("server/gl/Meshes.h:2: "), found[0])
        self.assertIn("server/gl may not include server/scene", found[0])

    def test_an_exception_allows_only_its_files_and_headers(self):
        self.assertEqual(self.problems({"server/gl/Upload.cpp": '#include "scene/Mesh.h"\n'}), [])
        self.assertEqual(len(self.problems({"server/gl/Draw.cpp": '#include "scene/Mesh.h"\n'})), 1)

    def test_unknown_includes_folders_and_entries_are_problems(self):
        found = self.problems({
            "server/gl/Context.h": '#include "gl/Missing.h"\n',
            "client/view/Main.cpp": "",
            "docs/layers.md": PAGE.replace("server/scene/Mesh.h", "server/scene/Mesh.hpp"),
        })
        self.assertEqual(len(found), 3, found)
        self.assertIn("docs/layers.md: 'server/scene/Mesh.hpp' names no folder or file", found)
        self.assertIn('server/gl/Context.h:1: #include "gl/Missing.h" is not a file of this repository', found)
        self.assertIn("client/view/Main.cpp: its folder has no row in docs/layers.md", found)


if __name__ == "__main__":
    unittest.main()
