#!/usr/bin/env python3
"""Checks the structural rules of the source tree (docs/architecture.md):

1. layers: a module depends only on modules of lower layers (vtk.module files);
2. includes: a module's files include only its own headers and those of the
   modules it declares; no include cycle between classes anywhere;
3. sizes: no production source file over 1,500 lines, no production function
   over 150 lines, README.md at most 250 lines;
4. refinement modes: every enum and ParaView XML entry that names the budget
   and fixed-accuracy refinement modes gives them the same integers.

Prints every violation and exits 1 if there is any. Run by ctest as HouseRules.
"""
import argparse
import re
import sys
from pathlib import Path

# Layer of each module: a module may depend only on modules of a lower layer.
LAYERS = {
    "TimeCritical::MeshCore": 0,
    "TimeCritical::BudgetCore": 0,
    "TimeCritical::Filters": 1,
    "TimeCritical::Rendering": 2,
    "TimeCritical::Views": 3,
}
PRODUCTION_DIRS = ("Core", "Filters", "Rendering", "Plugin")
SOURCE_SUFFIXES = (".h", ".cxx", ".inl", ".txx")
MAX_FILE_LINES = 1500
MAX_FUNCTION_LINES = 150
MAX_README_LINES = 250
MODE_NAMES = {"BUDGET": "budget", "TRIANGLE_BUDGET": "budget", "FIXED_ACCURACY": "fixed accuracy"}
XML_MODE_TEXTS = {"budget": "budget", "triangle budget": "budget", "fixed accuracy": "fixed accuracy"}


def read_module(path):
    """NAME, DEPENDS and PRIVATE_DEPENDS of a vtk.module file."""
    fields, key = {}, None
    for line in path.read_text().splitlines():
        if not line.strip():
            continue
        if not line.startswith(" "):
            key = line.strip()
            fields.setdefault(key, [])
        elif key:
            fields[key].append(line.strip())
    return {
        "name": fields["NAME"][0],
        "depends": fields.get("DEPENDS", []) + fields.get("PRIVATE_DEPENDS", []),
        "dir": path.parent,
    }


def check_layers(modules):
    errors = []
    for module in modules.values():
        layer = LAYERS.get(module["name"])
        if layer is None:
            errors.append(f"{module['dir']}/vtk.module: {module['name']} has no layer in check_house_rules.py")
            continue
        for dep in module["depends"]:
            if dep in LAYERS and LAYERS[dep] >= layer:
                errors.append(f"{module['name']} (layer {layer}) depends on {dep} (layer {LAYERS[dep]})")
    return errors


def source_files(directory):
    return sorted(p for p in directory.rglob("*") if p.suffix in SOURCE_SUFFIXES and p.is_file())


def owning_module(path, modules):
    """The module whose folder holds path most closely."""
    best = None
    for module in modules.values():
        try:
            path.relative_to(module["dir"])
        except ValueError:
            continue
        if best is None or len(module["dir"].parts) > len(best["dir"].parts):
            best = module
    return best


def includes(path):
    return re.findall(r'^\s*#\s*include\s+"([^"]+)"', path.read_text(errors="replace"), re.M)


def class_of(path):
    """Files of one class share a stem; the private parts of a split class
    (vtkFooInternals.h, vtkFooColors.cxx) are grouped by the longest class stem
    they start with, so only includes between different classes count."""
    return path.stem


def check_includes(root, modules):
    errors = []
    headers = {}
    for directory in PRODUCTION_DIRS:
        for path in source_files(root / directory):
            if path.suffix in (".h", ".inl", ".txx"):
                headers.setdefault(path.name, path)
    stems = sorted({p.stem for p in headers.values()}, key=len, reverse=True)

    def group(stem):
        for candidate in stems:
            if stem.startswith(candidate) and candidate != stem and len(candidate) >= 8:
                return candidate
        return stem

    edges = {}
    for directory in PRODUCTION_DIRS:
        for path in source_files(root / directory):
            module = owning_module(path, modules)
            allowed = {module["name"], *module["depends"]} if module else set()
            for name in includes(path):
                target = headers.get(Path(name).name)
                if target is None:
                    continue  # VTK, ParaView, generated or system header
                target_module = owning_module(target, modules)
                if module and target_module and target_module["name"] not in allowed:
                    errors.append(f"{path.relative_to(root)} includes {name} of {target_module['name']}, "
                                  f"which {module['name']} does not depend on")
                a, b = group(path.stem), group(target.stem)
                if a != b:
                    edges.setdefault(a, set()).add(b)
    errors += [f"include cycle between classes: {' -> '.join(cycle)}" for cycle in find_cycles(edges)]
    return errors


def find_cycles(edges):
    """One representative cycle per strongly connected component of size > 1."""
    index, low, on_stack, stack, result, counter = {}, {}, set(), [], [], [0]

    def visit(v):
        index[v] = low[v] = counter[0]
        counter[0] += 1
        stack.append(v)
        on_stack.add(v)
        for w in sorted(edges.get(v, ())):
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on_stack:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            component = []
            while True:
                w = stack.pop()
                on_stack.discard(w)
                component.append(w)
                if w == v:
                    break
            if len(component) > 1:
                result.append(sorted(component) + [sorted(component)[0]])

    sys.setrecursionlimit(10000)
    for v in sorted(edges):
        if v not in index:
            visit(v)
    return result


def strip_code(text):
    """Source with comments, strings and character literals blanked, lines kept."""
    text = re.sub(r"/\*.*?\*/", lambda m: "\n" * m.group(0).count("\n"), text, flags=re.S)
    text = re.sub(r"//[^\n]*", "", text)
    text = re.sub(r'R"(\w*)\(.*?\)\1"', lambda m: "\n" * m.group(0).count("\n"), text, flags=re.S)
    text = re.sub(r'"(\\.|[^"\\\n])*"', '""', text)
    return re.sub(r"'(\\.|[^'\\\n])*'", "''", text)


FUNCTION_HEAD = re.compile(r"\)\s*(const\s*)?(noexcept\s*)?(override\s*)?(final\s*)?(->\s*[\w:<>,\s\*&]+)?$")
NOT_FUNCTION = re.compile(r"^\s*(if|for|while|switch|catch|else|do)\b|\b(class|struct|enum|namespace|union)\b|=\s*$|\[.*\]\s*\(")


def long_functions(path):
    """(first line, length, head) of every brace block that is a function body longer than the limit."""
    lines = strip_code(path.read_text(errors="replace")).split("\n")
    found, stack = [], []
    for number, line in enumerate(lines):
        for ch in line:
            if ch == "{":
                head = ""
                for back in range(number, max(number - 8, -1), -1):
                    candidate = lines[back].split("{")[0] if back == number else lines[back]
                    head = (candidate.strip() + " " + head).strip()
                    if "(" in head or ";" in candidate or "}" in candidate:
                        break
                head = head.split(";")[-1].split("}")[-1].strip()
                is_function = bool(FUNCTION_HEAD.search(head.split("{")[0].strip())) and not NOT_FUNCTION.search(head)
                inside_function = any(entry[1] for entry in stack)
                stack.append((number, is_function and not inside_function, head))
            elif ch == "}" and stack:
                start, is_function, head = stack.pop()
                length = number - start + 1
                if is_function and length > MAX_FUNCTION_LINES:
                    found.append((start + 1, length, head))
    return found


def check_sizes(root):
    errors = []
    for directory in PRODUCTION_DIRS:
        for path in source_files(root / directory):
            count = len(path.read_text(errors="replace").splitlines())
            if count > MAX_FILE_LINES:
                errors.append(f"{path.relative_to(root)}: {count} lines (at most {MAX_FILE_LINES})")
            for line, length, head in long_functions(path):
                errors.append(f"{path.relative_to(root)}:{line}: function of {length} lines "
                              f"(at most {MAX_FUNCTION_LINES}): {head[:80]}")
    readme = root / "README.md"
    count = len(readme.read_text().splitlines())
    if count > MAX_README_LINES:
        errors.append(f"README.md: {count} lines (at most {MAX_README_LINES})")
    return errors


def check_refinement_modes(root):
    """Every enum value and XML entry naming a refinement mode gives it one integer."""
    values = {}
    for directory in PRODUCTION_DIRS:
        for path in source_files(root / directory):
            for name, value in re.findall(r"\b(BUDGET|TRIANGLE_BUDGET|FIXED_ACCURACY)\s*=\s*(\d+)",
                                          strip_code(path.read_text(errors="replace"))):
                values.setdefault(MODE_NAMES[name], set()).add((int(value), f"{path.relative_to(root)} {name}"))
    for path in sorted((root / "Plugin").glob("*.xml")):
        text = path.read_text()
        for prop in re.finditer(r'<IntVectorProperty[^>]*name="(\w*Refinement\w*Mode\w*)".*?</IntVectorProperty>', text, re.S):
            for value, label in re.findall(r'<Entry\s+value="(\d+)"\s+text="([^"]+)"', prop.group(0)):
                mode = XML_MODE_TEXTS.get(label.lower())
                if mode:
                    values.setdefault(mode, set()).add((int(value), f"{path.relative_to(root)} {prop.group(1)}={label}"))
    errors = []
    for mode, found in sorted(values.items()):
        if len({value for value, _ in found}) > 1:
            listed = ", ".join(f"{where}={value}" for value, where in sorted(found))
            errors.append(f"refinement mode '{mode}' has several integers: {listed}")
    if not values:
        errors.append("no refinement mode enum or XML entry found (has the check gone stale?)")
    return errors


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--root", type=Path, default=Path(__file__).resolve().parent.parent)
    args = parser.parse_args()
    root = args.root.resolve()
    modules = {}
    for path in sorted(root.glob("**/vtk.module")):
        if any(part.startswith(("build", ".")) for part in path.relative_to(root).parts):
            continue
        module = read_module(path)
        modules[module["name"]] = module
    errors = (check_layers(modules) + check_includes(root, modules) + check_sizes(root)
              + check_refinement_modes(root))
    for error in errors:
        print(f"house rules: {error}")
    print(f"house rules: {len(modules)} modules, {len(errors)} violation(s)")
    return 1 if errors else 0


if __name__ == "__main__":
    sys.exit(main())
