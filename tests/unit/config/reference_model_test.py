#!/usr/bin/env python3
"""config.reference_model: config/reefscape-2025-elevator-pivot-wrist.toml says what the reference
model it encodes says, and config/intake-pivot.toml is a one-joint description.

Usage: reference_model_test.py SOURCE_DIR

The reference model is tests/fixtures/reference/reefscape-2025-elevator-pivot-wrist.json (its
format: tests/fixtures/reference/README.md). Every joint, link polygon, piece, obstacle, scene,
motor, drive figure and named pose of the TOML must equal the JSON's, keys as
docs/configuration.md names them, numbers to 1e-12 relative; nothing may be missing or extra
(a piece's mass data and a scene's obstacle lists and offset range left out either side count at
their documented defaults; a drive's cg along the link is [cg, 0]). One key is the project's own
addition, not the model's: the reef scene's offset_range_m = [0.0, 0.3], the band of scene offsets
the other shipped robots plan in (the model gives none); it must be exactly that, or absent. Then every number of the TOML
is changed in turn, by 1e-9 relative (integers by 1), and each change must be reported: the
comparison cannot pass a file that differs.

The loader (config_loader/) is not used: this checks the data, whichever joint counts the loader
takes. Prints one line per difference; exits 1 if there is any.
"""
import json
import math
import os
import re
import sys
import tomllib

THREE_JOINTS = "config/reefscape-2025-elevator-pivot-wrist.toml"
REFERENCE = "tests/fixtures/reference/reefscape-2025-elevator-pivot-wrist.json"
ONE_JOINT = "config/intake-pivot.toml"
RELATIVE = 1e-12

# JSON key -> TOML key, for the tables whose keys differ only by their unit.
MOTOR_KEYS = {"nominal_voltage": "nominal_voltage_volts", "stall_torque": "stall_torque_nm",
              "stall_current": "stall_current_amps", "free_current": "free_current_amps",
              "free_speed_rpm": "free_speed_rpm"}
DRIVE_KEYS = {"kind": "kind", "motor": "motor", "count": "count", "gearing": "gearing", "kS": "kS_volts",
              "gravity": "gravity", "kG": "kG_volts", "kV": "kV", "kA": "kA", "mass": "mass_kg", "cg": "cg_m",
              "moi": "moi_kgm2", "voltage_limit": "voltage_limit_volts", "current_limit": "current_limit_amps"}
# Joint limits of the model live in the TOML's drive of that joint.
LIMIT_KEYS = {"velocity": "velocity_limit", "acceleration": "acceleration_limit"}
# The project's own additions to the model, each allowed exactly as written here: scene name ->
# offset_range_m where the model gives the scene none (the range the other shipped robots plan in).
PROJECT_OFFSET_RANGES = {"reef": [0.0, 0.3]}
# Keys of the model that are words for people, not data.
PROSE = {"about", "units", "frame", "format", "gearing_units"}


class Report:
    def __init__(self):
        self.lines = []

    def differ(self, where, json_value, toml_value):
        self.lines.append(f"{where}: the model has {json_value!r}, the TOML {toml_value!r}")

    def fail(self, where, problem):
        self.lines.append(f"{where}: {problem}")


def same_number(a, b):
    if isinstance(a, bool) or isinstance(b, bool) or not isinstance(a, (int, float)) or not isinstance(b, (int, float)):
        return False
    if isinstance(a, int) and isinstance(b, int):
        return a == b
    return math.isclose(a, b, rel_tol=RELATIVE, abs_tol=0.0)


def compare(where, json_value, toml_value, report):
    """Numbers to RELATIVE, lists element by element, anything else exactly."""
    if isinstance(json_value, list) and isinstance(toml_value, list):
        if len(json_value) != len(toml_value):
            report.differ(where + " (length)", len(json_value), len(toml_value))
            return
        for i, (a, b) in enumerate(zip(json_value, toml_value)):
            compare(f"{where}[{i}]", a, b, report)
    elif isinstance(json_value, (int, float)) and not isinstance(json_value, bool):
        if not same_number(json_value, toml_value):
            report.differ(where, json_value, toml_value)
    elif json_value != toml_value:
        report.differ(where, json_value, toml_value)


def same_keys(where, json_keys, toml_keys, report):
    json_keys, toml_keys = set(json_keys) - PROSE, set(toml_keys)
    for key in sorted(json_keys - toml_keys):
        report.fail(where, f"'{key}' is in the model, not in the TOML")
    for key in sorted(toml_keys - json_keys):
        report.fail(where, f"'{key}' is in the TOML, not in the model")
    return sorted(json_keys & toml_keys)


def vertex_mean(polygons):
    vertices = [v for polygon in polygons for v in polygon]
    return [sum(v[0] for v in vertices) / len(vertices), sum(v[1] for v in vertices) / len(vertices)]


def point(cg):
    # A cg along the link's x axis is the point [cg, 0] of its frame (docs/configuration.md).
    return [cg, 0.0] if isinstance(cg, (int, float)) else cg


def compare_joints(model, toml, report):
    joints = toml.get("joints", [])
    if len(joints) != len(model["joints"]):
        report.differ("joints (count)", len(model["joints"]), len(joints))
        return
    for i, (j, t) in enumerate(zip(model["joints"], joints)):
        keys = {"name": "name", "type": "type", "min": "min", "max": "max", "origin": "origin_m",
                "axis_deg": "axis_deg"}
        for key in sorted(set(j) - PROSE - set(keys) - {"limits"}):
            report.fail(f"joints[{i}]", f"the model's '{key}' has no TOML key")
        for key in sorted(set(t) - set(keys.values())):
            report.fail(f"joints[{i}]", f"'{key}' is in the TOML, not in the model")
        for json_key, toml_key in keys.items():
            compare(f"joints[{i}].{toml_key}", j.get(json_key), t.get(toml_key), report)


def compare_outlines(model, toml, report):
    joint_names = [j["name"] for j in model["joints"]]
    # Model key -> TOML key; a link has only the first two.
    keys = {"joint": "joint", "polygons": "polygons", "mass": "mass_kg", "cg": "cg_m", "moi": "moi_kgm2"}
    for table in ("links", "pieces"):
        allowed = dict(list(keys.items())[:2]) if table == "links" else keys
        mine = toml.get(table, {})
        for name in same_keys(table, model.get(table, {}), mine, report):
            j, t = model[table][name], mine[name]
            where = f"{table}.{name}"
            for key in sorted(set(j) - PROSE - set(allowed)):
                report.fail(where, f"the model's '{key}' has no TOML key")
            for key in sorted(set(t) - set(allowed.values())):
                report.fail(where, f"'{key}' is not a key of {table}")
            index = j["joint"]
            compare(where + ".joint", joint_names[index] if 0 <= index < len(joint_names) else index, t.get("joint"),
                    report)
            compare(where + ".polygons", j["polygons"], t.get("polygons"), report)
            if table == "pieces":
                # Defaults of docs/configuration.md: weightless, cg at the vertices' mean, a point mass.
                compare(where + ".mass_kg", j.get("mass", 0.0), t.get("mass_kg", 0.0), report)
                compare(where + ".cg_m", point(j.get("cg", vertex_mean(j["polygons"]))),
                        point(t.get("cg_m", vertex_mean(t.get("polygons", j["polygons"])))), report)
                compare(where + ".moi_kgm2", j.get("moi", 0.0), t.get("moi_kgm2", 0.0), report)


def compare_world(model, toml, report):
    obstacles = toml.get("obstacles", {})
    for name in same_keys("obstacles", model["obstacles"], obstacles, report):
        compare(f"obstacles.{name}", model["obstacles"][name], obstacles[name], report)
    scenes = toml.get("scenes", [])
    if len(scenes) != len(model["scenes"]):
        report.differ("scenes (count)", len(model["scenes"]), len(scenes))
        return
    for i, (j, t) in enumerate(zip(model["scenes"], scenes)):
        for key in sorted(set(t) - {"name", "obstacles", "fixed", "offset_range_m"}):
            report.fail(f"scenes[{i}]", f"'{key}' is in the TOML, not in the model")
        compare(f"scenes[{i}].name", j["name"], t.get("name"), report)
        compare(f"scenes[{i}].obstacles", j.get("obstacles", []), t.get("obstacles", []), report)
        compare(f"scenes[{i}].fixed", j.get("fixed", []), t.get("fixed", []), report)
        # Without a range a scene is planned as drawn: offset 0 only, unless the project adds its own.
        default = [0.0, 0.0]
        if "offset_range" not in j and "offset_range_m" in t:
            default = PROJECT_OFFSET_RANGES.get(j["name"], default)
        compare(f"scenes[{i}].offset_range_m", j.get("offset_range", default), t.get("offset_range_m", [0.0, 0.0]),
                report)
    compare("clearance_m", model["clearance"], toml.get("clearance_m"), report)
    compare("name", model["name"], toml.get("name"), report)


def compare_table(where, model_table, toml_table, keys, report):
    for key in sorted(set(model_table) - PROSE - set(keys)):
        report.fail(where, f"the model's '{key}' has no TOML key")
    toml_keys = {keys[k] for k in model_table if k in keys}
    for key in sorted(set(toml_table) - toml_keys):
        report.fail(where, f"'{key}' is in the TOML, not in the model")
    for json_key, toml_key in keys.items():
        if json_key in model_table:
            value = model_table[json_key]
            toml_value = toml_table.get(toml_key)
            if json_key == "cg":
                value, toml_value = point(value), point(toml_value) if toml_value is not None else None
            compare(f"{where}.{toml_key}", value, toml_value, report)


def compare_drives(model, toml, report):
    motors = toml.get("motors", {})
    for name in same_keys("motors", model["motors"], motors, report):
        compare_table(f"motors.{name}", model["motors"][name], motors[name], MOTOR_KEYS, report)
    drives = toml.get("drives", {})
    for name in same_keys("drives", model["drives"], drives, report):
        limits = next((j.get("limits", {}) for j in model["joints"] if j["name"] == name), {})
        for key in sorted(set(limits) - set(LIMIT_KEYS)):
            report.fail(f"joints.{name}.limits", f"the model's '{key}' limit has no TOML key")
        with_limits = dict(model["drives"][name], **{k: v for k, v in limits.items() if k in LIMIT_KEYS})
        compare_table(f"drives.{name}", with_limits, drives[name], dict(DRIVE_KEYS, **LIMIT_KEYS), report)


def compare_poses(model, toml, report):
    poses = toml.get("poses", {})
    for held in same_keys("poses", model.get("poses", {}), poses, report):
        for name in same_keys(f"poses.{held}", model["poses"][held], poses[held], report):
            compare(f"poses.{held}.{name}", model["poses"][held][name], poses[held][name], report)


# Top-level tables of the model, and the TOML's besides them: the planner's and daemon's settings
# are the project's, not the model's, and are not compared.
MODEL_TABLES = {"name", "clearance", "joints", "links", "pieces", "obstacles", "scenes", "motors", "drives", "poses"}
TOML_TABLES = {"name", "clearance_m", "joints", "links", "pieces", "obstacles", "scenes", "motors", "drives", "poses",
               "planner", "daemon"}


def differences(model, toml):
    report = Report()
    for key in sorted(set(model) - PROSE - MODEL_TABLES):
        report.fail("model", f"'{key}' is not compared")
    for key in sorted(set(toml) - TOML_TABLES):
        report.fail("TOML", f"'{key}' is not in the model")
    compare_joints(model, toml, report)
    compare_outlines(model, toml, report)
    compare_world(model, toml, report)
    compare_drives(model, toml, report)
    compare_poses(model, toml, report)
    return report.lines


# A number of a TOML value: not inside a word (kraken_x60_foc), a string or a comment.
NUMBER = re.compile(r"(?<![\w.\-])-?\d+(?:\.\d+)?(?:[eE][-+]?\d+)?(?![\w.])")


def numbers_of(text):
    """(start, end) of every number in the TOML's values."""
    spans = []
    offset = 0
    for line in text.splitlines(keepends=True):
        code = line.split("#", 1)[0]
        for m in NUMBER.finditer(code):
            if code[:m.start()].count('"') % 2 == 0:
                spans.append((offset + m.start(), offset + m.end()))
        offset += len(line)
    return spans


def numbers_in(value):
    """The model's numbers that the TOML writes as numbers (not a link's or piece's joint index)."""
    if isinstance(value, dict):
        return sum(numbers_in(v) for k, v in value.items() if k not in PROSE and k != "joint")
    if isinstance(value, list):
        return sum(numbers_in(v) for v in value)
    return 1 if isinstance(value, (int, float)) and not isinstance(value, bool) else 0


def changed(token):
    if re.fullmatch(r"-?\d+", token):
        return str(int(token) + 1)
    value = float(token)
    return repr(value * (1 + 1e-9) if value != 0.0 else 1e-9)


def check_every_number_counts(model, text, failures):
    spans = numbers_of(text)
    # Each of the model's numbers is written once: fewer found means the scan missed some.
    if len(spans) < numbers_in(model):
        failures.append(f"{THREE_JOINTS}: {len(spans)} numbers found to change, the model has {numbers_in(model)}")
    for start, end in spans:
        mutated = text[:start] + changed(text[start:end]) + text[end:]
        if not differences(model, tomllib.loads(mutated)):
            line = text.count("\n", 0, start) + 1
            failures.append(f"{THREE_JOINTS}:{line}: {text[start:end]} -> {changed(text[start:end])} is not reported")
    return len(spans)


def check_one_joint(source_dir, failures):
    with open(os.path.join(source_dir, ONE_JOINT), "rb") as f:
        robot = tomllib.load(f)
    joints = robot.get("joints", [])
    if len(joints) != 1:
        failures.append(f"{ONE_JOINT}: {len(joints)} joints, not 1")
        return
    name = joints[0]["name"]
    if set(robot.get("drives", {})) != {name}:
        failures.append(f"{ONE_JOINT}: drives {sorted(robot.get('drives', {}))}, not the joint's '{name}'")
    for table in ("links", "pieces"):
        for outline, body in robot.get(table, {}).items():
            if body.get("joint") != name:
                failures.append(f"{ONE_JOINT}: {table}.{outline} is on '{body.get('joint')}', not '{name}'")
    for held, poses in robot.get("poses", {}).items():
        for pose, q in poses.items():
            if len(q) != 1 or not joints[0]["min"] <= q[0] <= joints[0]["max"]:
                failures.append(f"{ONE_JOINT}: poses.{held}.{pose} = {q} is not one value in the joint's range")


def main():
    if len(sys.argv) != 2:
        print(__doc__, file=sys.stderr)
        return 2
    source_dir = sys.argv[1]
    with open(os.path.join(source_dir, REFERENCE), encoding="utf-8") as f:
        model = json.load(f)
    with open(os.path.join(source_dir, THREE_JOINTS), encoding="utf-8") as f:
        text = f.read()
    failures = [f"{THREE_JOINTS}: {line}" for line in differences(model, tomllib.loads(text))]
    count = 0
    if not failures:  # a sweep over a file that already differs says nothing
        count = check_every_number_counts(model, text, failures)
    check_one_joint(source_dir, failures)
    for line in failures:
        print(line)
    if failures:
        return 1
    print(f"{THREE_JOINTS} equals {REFERENCE}; each of its {count} numbers changed is reported; "
          f"{ONE_JOINT} has one joint")
    return 0


if __name__ == "__main__":
    sys.exit(main())
