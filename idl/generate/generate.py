#!/usr/bin/env python3
"""Generates plumb's message layer from idl/*.idl, the way rosidl generates type support:

  generate.py topics     OUT FILE.idl...  vendor-neutral C++ types and the topic table
  generate.py cyclonedds OUT FILE.idl...  conversions to idlc's C structs, Cyclone type support
  generate.py fastdds    OUT FILE.idl...  conversions to fastddsgen's classes, Fast DDS type support

Run by CMake at build time (idl/CMakeLists.txt); the output lives in the build tree only. An IDL
construct outside plumb's subset stops the build with file:line: error: ...
"""

import os
import sys

sys.dont_write_bytecode = True  # nothing generated in the source tree, not even __pycache__
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

import emit_cyclonedds  # noqa: E402
import emit_fastdds  # noqa: E402
import emit_topics  # noqa: E402
from idl_parser import IdlError, parse_files  # noqa: E402

EMITTERS = {"topics": emit_topics, "cyclonedds": emit_cyclonedds, "fastdds": emit_fastdds}


def write(path, text):
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w", encoding="utf-8") as f:
        f.write(text)


def main(argv):
    if len(argv) < 4 or argv[1] not in EMITTERS:
        print(__doc__, file=sys.stderr)
        return 2
    language, out_dir, paths = argv[1], argv[2], argv[3:]
    try:
        files, structs = parse_files(paths)
        outputs = EMITTERS[language].emit(files, structs)
    except IdlError as e:
        print(e, file=sys.stderr)
        return 1
    for relative, text in outputs.items():
        write(os.path.join(out_dir, relative), text)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
