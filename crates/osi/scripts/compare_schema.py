#!/usr/bin/env python3
"""Compare the osi3 schema embedded in an oscsim .mcap trace with the official OSI bindings.

Usage:  python3 compare_schema.py TRACE.mcap

Reads the schema record of the trace's osi3.GroundTruth channel (a binary
FileDescriptorSet), and checks every message, field and enum value in it against the
descriptors of the installed official bindings (osi-python): same field names, numbers,
types, labels, message/enum type names, enum value names and numbers. oscsim writes a
subset of OSI, so fields the official schema has and oscsim's lacks are only counted.
Prints one line per mismatch, then "N passed, M failed" (messages and enums checked).
Exit status 0 only when nothing differs.
"""
import sys
from mcap.reader import make_reader
from google.protobuf import descriptor_pb2, descriptor_pool
import osi3.osi_groundtruth_pb2  # noqa: F401  (registers the official descriptors)


def official(full_name):
    pool = descriptor_pool.Default()
    try:
        return pool.FindMessageTypeByName(full_name)
    except KeyError:
        return None


def official_enum(full_name):
    try:
        return descriptor_pool.Default().FindEnumTypeByName(full_name)
    except KeyError:
        return None


def main():
    path = sys.argv[1]
    with open(path, "rb") as f:
        summary = make_reader(f).get_summary()
    schemas = [s for s in summary.schemas.values() if s.name == "osi3.GroundTruth"]
    if len(schemas) != 1 or schemas[0].encoding != "protobuf":
        print(f"{path}: expected one protobuf schema osi3.GroundTruth")
        return 1
    fds = descriptor_pb2.FileDescriptorSet()
    fds.ParseFromString(schemas[0].data)

    problems, passed, failed, left_out = [], 0, 0, 0

    def check_enum(prefix, e):
        nonlocal passed, failed
        name = f"{prefix}.{e.name}"
        off = official_enum(name)
        if off is None:
            problems.append(f"enum {name}: not in the official schema")
            failed += 1
            return
        ours = {(v.name, v.number) for v in e.value}
        theirs = {(v.name, v.number) for v in off.values}
        if ours != theirs:
            problems.append(f"enum {name}: values differ: ours-only {sorted(ours - theirs)}, official-only {sorted(theirs - ours)}")
            failed += 1
        else:
            passed += 1

    def check_message(prefix, m):
        nonlocal passed, failed, left_out
        name = f"{prefix}.{m.name}"
        off = official(name)
        if off is None:
            problems.append(f"message {name}: not in the official schema")
            failed += 1
            return
        bad = False
        by_number = {f.number: f for f in off.fields}
        for f in m.field:
            o = by_number.get(f.number)
            if o is None:
                problems.append(f"{name}.{f.name} = {f.number}: no such field number in the official schema")
                bad = True
                continue
            o_type_name = ("." + (o.message_type or o.enum_type).full_name) if (o.message_type or o.enum_type) else ""
            o_label = 3 if o.is_repeated else 1
            mine = (f.name, f.type, f.label, f.type_name)
            theirs = (o.name, o.type, o_label, o_type_name)
            if mine != theirs:
                problems.append(f"{name} field {f.number}: ours {mine}, official {theirs}")
                bad = True
        left_out += len(by_number) - len(m.field)
        if bad:
            failed += 1
        else:
            passed += 1
        for e in m.enum_type:
            check_enum(name, e)
        for n in m.nested_type:
            check_message(name, n)

    for file in fds.file:
        prefix = file.package
        for e in file.enum_type:
            check_enum(prefix, e)
        for m in file.message_type:
            check_message(prefix, m)
    for p in problems[:50]:
        print(p)
    print(f"schema of {path}: {left_out} official fields not written by oscsim")
    print(f"{passed} passed, {failed} failed")
    return 0 if failed == 0 else 1


if __name__ == "__main__":
    sys.exit(main())
