#!/usr/bin/env python3
"""Validates scene files against `softbody schema` with a real validator (python3-jsonschema, draft 2020-12).

Every scene of scenes/, scenes/gallery/ and the tests must validate; every scene of tests/schema/bad/ must be
refused by both the schema and the parser (`softbody simulate` exits 2, bad input).

Usage: validate_scenes.py SOFTBODY SOURCE_DIR
"""
import json
import pathlib
import re
import subprocess
import sys
import tempfile

from jsonschema import Draft202012Validator

EXIT_BAD_INPUT = 2  # src/core/errors.hpp

# The hostile scenes (tests/data/hostile/) are hostile in ways a schema can or cannot say: those it can are
# refused, the others (file contents, run lengths, frame patterns) validate and are the parser's or the run's.
HOSTILE_REFUSED_BY_SCHEMA = {
    "deep_file.json",  # not an object
    "deep_value.json",  # a mass that is an array
    "name_dotdot.json",  # name "..": refused
    "name_300_bytes.json",  # beyond maxLength 255
    "name_nul.json",  # a control character: the pattern refuses it
    "output_dir_newline.json",  # the same
    "position_1e308.json",  # beyond +-1e6
    "scale_1e200.json",  # beyond 1e6
    "scale_1e-200.json",  # below 1e-6
}
HOSTILE_NOT_READABLE = {"number_1e400.json"}  # Python reads 1e400 as inf; the parser refuses it before a schema


def strip_comments(text):
    """Removes // and /* */ comments outside strings, as the parser does (nlohmann's ignore_comments)."""
    out = []
    i, n = 0, len(text)
    in_string = False
    while i < n:
        c = text[i]
        if in_string:
            out.append(c)
            if c == "\\" and i + 1 < n:
                out.append(text[i + 1])
                i += 1
            elif c == '"':
                in_string = False
        elif c == '"':
            in_string = True
            out.append(c)
        elif text.startswith("//", i):
            end = text.find("\n", i)
            i = n if end < 0 else end
            continue
        elif text.startswith("/*", i):
            end = text.find("*/", i + 2)
            if end < 0:
                raise ValueError("unterminated /* comment")
            out.append(" ")
            i = end + 2
            continue
        else:
            out.append(c)
        i += 1
    return "".join(out)


def load_scene(path):
    sys.setrecursionlimit(10000)
    return json.loads(strip_comments(path.read_text(encoding="utf-8")))


def schema_errors(validator, path):
    try:
        document = load_scene(path)
    except (ValueError, RecursionError) as e:
        return [f"not readable: {type(e).__name__}"]
    return [f"{'.'.join(map(str, e.absolute_path)) or '(top level)'}: {e.message}"
            for e in validator.iter_errors(document)]


def error_paths(validator, document):
    """The key path ("bodies.0.mass") of every error, with those of the alternatives an anyOf tried."""
    paths = set()
    pending = list(validator.iter_errors(document))
    while pending:
        error = pending.pop()
        paths.add(".".join(str(part) for part in error.absolute_path))
        pending += error.context or []
    return paths


def names_key(schema_path, key):
    """True when an error at schema_path is about key: the key itself or the object that holds it."""
    return schema_path == key or key.startswith(schema_path + ".") or (schema_path == "" and "." not in key)


def refused_by_both(softbody, validator, path, source):
    """A bad scene's first line says where it is bad: // refused at KEY: why."""
    match = re.match(r"// refused at (\S+): ", path.read_text(encoding="utf-8"))
    if not match:
        print(f"FAIL  {path.relative_to(source)}: its first line should be // refused at KEY: why")
        return False
    key = match.group(1)
    schema_paths = error_paths(validator, load_scene(path))
    with tempfile.TemporaryDirectory() as scratch:
        run = subprocess.run([softbody, "simulate", str(path), "--csv", str(pathlib.Path(scratch) / "a.csv")],
                             capture_output=True, text=True, timeout=120)
    message = run.stderr.strip().splitlines()[-1] if run.stderr.strip() else ""
    schema_ok = any(names_key(p, key) for p in schema_paths)
    parser_ok = run.returncode == EXIT_BAD_INPUT and f": {key}: " in message
    print(("ok    " if schema_ok and parser_ok else "FAIL  ") + f"{path.relative_to(source)} refused at {key}")
    print(f"      schema: errors at {sorted(schema_paths) or '(none: accepted)'}")
    print(f"      parser: exit {run.returncode}: {message}")
    return schema_ok and parser_ok


def main():
    softbody, source = sys.argv[1], pathlib.Path(sys.argv[2])
    schema = json.loads(subprocess.run([softbody, "schema"], check=True, capture_output=True, text=True).stdout)
    Draft202012Validator.check_schema(schema)
    if schema.get("$schema") != "https://json-schema.org/draft/2020-12/schema":
        print("FAIL: the schema does not name draft 2020-12")
        return 1
    validator = Draft202012Validator(schema)
    failures = 0

    valid = []
    for folder in ["scenes", "scenes/gallery", "tests/scenes", "tests/fuzz/corpus/fuzz_scene"]:
        valid += sorted((source / folder).glob("*.json"))
    hostile = sorted((source / "tests/data/hostile").glob("*.json"))
    valid += [p for p in hostile if p.name not in HOSTILE_REFUSED_BY_SCHEMA | HOSTILE_NOT_READABLE]
    for path in valid:
        errors = schema_errors(validator, path)
        print(("ok    " if not errors else "FAIL  ") + str(path.relative_to(source)))
        for error in errors:
            print("      " + error)
        failures += bool(errors)

    # A scene may name its schema.
    with tempfile.TemporaryDirectory() as scratch:
        named = pathlib.Path(scratch) / "named.json"
        document = load_scene(source / "scenes/bounce.json")
        document["$schema"] = "https://example.org/softbody-scene.schema.json"
        named.write_text(json.dumps(document))
        errors = schema_errors(validator, named)
        print(("ok    " if not errors else "FAIL  ") + "scenes/bounce.json with \"$schema\"")
        failures += bool(errors)

    refused = [p for p in hostile if p.name in HOSTILE_REFUSED_BY_SCHEMA]
    for path in refused:
        ok = bool(schema_errors(validator, path))
        print(("ok    " if ok else "FAIL  ") + str(path.relative_to(source)) + " refused by the schema")
        failures += not ok

    bad = sorted((source / "tests/schema/bad").glob("*.json"))
    if len(bad) < 10:
        print(f"FAIL: expected at least 10 bad scenes in tests/schema/bad, found {len(bad)}")
        failures += 1
    for path in bad:
        failures += not refused_by_both(softbody, validator, path, source)

    print(f"{failures} failure(s)")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
