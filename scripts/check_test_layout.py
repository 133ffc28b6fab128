#!/usr/bin/python3
# SPDX-License-Identifier: BSD-3-Clause
"""Checks that the tests mirror the source: every class of the production
folders has a test file of its own name, Testing/<folder>/Test<Class>.* (.cxx
or .py), in the folder that mirrors its header's.

The classes are the top-level classes and structs (not nested ones, not
enums) defined in the headers of PRODUCTION_FOLDERS. Plain data structs,
which hold no logic of their own, are listed in EXEMPT with the reason; a
class whose test is being written on another branch is listed in PENDING
with that branch's work. The private parts of a class in its internals
header <Class>Internals.h are covered by <Class>'s own tests. Both lists are
checked too: an entry that names no class of these headers, or a class that
has its test file by now, fails, so that they hold only what is true.

Exit status 0 when every class is tested or listed; 1 otherwise, naming each
class without its test file and the file it needs.

    scripts/check_test_layout.py [--source <repository root>] [--list]
"""

import argparse
import os
import re
import sys

PRODUCTION_FOLDERS = ["Core/Mesh", "Core/Budget", "Filters", "Rendering", "Plugin/Views"]

# Plain data: members and at most trivial accessors, whose behaviour is that
# of the classes that fill and read them (and is tested there).
EXEMPT = {
    # Core/Mesh
    "TOMMesh": "the TOM's arrays; filled by TOMBuilder, checked by TOMValidator, read by TOMTraversal",
    "MergeTree": "the merge tree's arrays; filled by MergeTreeBuilder, read by ViewDependentRefinement",
    "TOMBuildOptions": "options struct of TOMBuilder (TestTOMBuilder)",
    "TOMBuildResult": "result struct of TOMBuilder (TestTOMBuilder)",
    "MergeTreeBuildOptions": "options struct of MergeTreeBuilder (TestMergeTreeBuilder)",
    "MergeTreeBuildResult": "result struct of MergeTreeBuilder (TestMergeTreeBuilder)",
    "MergeTreeErrorOptions": "options struct of the MergeTreeAttributes functions (TestMergeTreeAttributes)",
    "RefinementView": "input struct of ViewDependentRefinement: camera and thresholds (TestViewDependentRefinement)",
    "RefinementStatistics": "result struct of ViewDependentRefinement (TestViewDependentRefinement)",
    "LeafBuildMessage": "a message of BuildLeafHierarchy (LeafHierarchyBuild.h), reported by "
                        "vtkMultiresolutionHierarchyBuilder (TestvtkMultiresolutionHierarchyBuilder)",
    "LeafBuildResult": "result struct of BuildLeafHierarchy (LeafHierarchyBuild.h; "
                       "TestvtkMultiresolutionHierarchyBuilder)",
    "SettingCheck": "result struct of the Check*() functions of RefinementSettings.h (TestRefinementSettings)",
    "Tri": "the collapse engine's triangle: corners and flags, with two one-line lookups "
           "(CornerOf, Has); used throughout CollapseEngine (TestCollapseEngine, TestFanGroups)",
    "Vertex": "the collapse engine's per-vertex record, one cache line of fields (TestCollapseEngine)",
    "Candidate": "a collapse target and its cost, returned by CheapestTarget (TestCheapestTarget)",
    "ConstraintRecord": "a vertex's constraint Quadric and its weight, kept apart by CollapseEngine "
                        "(TestQuadric, TestCollapseEngine)",
    # Core/Budget
    "CostModelCalibratorOptions": "options struct of CostModelCalibrator (TestCostModelCalibrator)",
    "PolicyInput": "input struct of ResolutionPolicy::Select; its one derived view, GetProblem(), "
                   "is asserted in TestResolutionPolicy",
    "PolicyResult": "result struct of ResolutionPolicy::Select (TestResolutionPolicy)",
    # Filters
    "PreparedSurface": "result struct of PrepareSurface (TOMFilterSupport), filled for the builders",
    "CameraViewOptions": "options struct of RefinementViewFromCamera (TestRefinementViewFromCamera)",
}

# Classes whose Test<Class> file is being written on another branch, with
# that branch's work; the entry goes when that branch is merged (the check
# fails on a stale entry).
PENDING = {
}

# A private internals header <Owner>Internals.h holds the private parts of
# class <Owner>, which are tested through <Owner>'s own tests.
INTERNALS_SUFFIX = "Internals.h"

CLASS_PATTERN = re.compile(
    r"\b(class|struct)\s+"
    r"(?:alignas\s*\([^)]*\)\s*)?"
    r"(?:[A-Z][A-Z0-9_]*_EXPORT\s+)?"
    r"([A-Za-z_]\w*)\s*"
    r"(?:final\s*)?"
    r"([:{])")


def strip_comments_and_strings(text):
    """The text with comments, string and character literals blanked out
    (newlines kept), so that braces and keywords in them do not count."""
    pattern = re.compile(r'//[^\n]*|/\*.*?\*/|"(?:\\.|[^"\\\n])*"|\'(?:\\.|[^\'\\\n])*\'',
                         re.DOTALL)
    return pattern.sub(lambda m: re.sub(r"[^\n]", " ", m.group(0)), text)


def top_level_classes(text):
    """Names of the classes and structs defined at namespace scope in a header."""
    text = strip_comments_and_strings(text)
    # Scope kinds by the position of their opening brace.
    openers = {}
    for match in re.finditer(r"\bnamespace(?:\s+[\w:]+)?\s*\{", text):
        openers[match.end() - 1] = "namespace"
    for match in re.finditer(r'\bextern\s+"C"\s*\{', text):
        openers[match.end() - 1] = "namespace"
    classes_at = {}
    for match in CLASS_PATTERN.finditer(text):
        if re.search(r"\benum\s+$", text[max(0, match.start() - 10):match.start()]):
            continue  # enum class / enum struct
        brace = text.find("{", match.end(3) - 1)
        classes_at[match.start()] = (match.group(2), brace)
    names = []
    stack = []
    pending = sorted(classes_at.items())
    index = 0
    for position, char in enumerate(text):
        while index < len(pending) and pending[index][0] <= position:
            name, _ = pending[index][1]
            if all(kind == "namespace" for kind in stack):
                names.append(name)
            index += 1
        if char == "{":
            stack.append(openers.get(position, "other"))
        elif char == "}" and stack:
            stack.pop()
    return names


def production_classes(root):
    """(folder, class, header) for every top-level class of the production headers."""
    found = []
    for folder in PRODUCTION_FOLDERS:
        directory = os.path.join(root, folder)
        for header in sorted(os.listdir(directory)):
            if not header.endswith(".h"):
                continue
            with open(os.path.join(directory, header), encoding="utf-8") as stream:
                text = stream.read()
            for name in top_level_classes(text):
                found.append((folder, name, header))
    return found


def test_files(root, folder, name):
    """The test files of class `name`: Testing/<folder>/Test<name>.<extension>."""
    directory = os.path.join(root, "Testing", folder)
    if not os.path.isdir(directory):
        return []
    prefix = "Test" + name + "."
    return sorted(f for f in os.listdir(directory) if f.startswith(prefix))


def covering_files(root, folder, name, header):
    """The test files that cover class `name` of `header`: its own, or, for the
    private parts in an internals header <Owner>Internals.h, those of <Owner>."""
    files = test_files(root, folder, name)
    if not files and header.endswith(INTERNALS_SUFFIX):
        files = test_files(root, folder, header[:-len(INTERNALS_SUFFIX)])
    return files


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--source", default=os.path.dirname(os.path.dirname(os.path.abspath(__file__))),
                        help="the repository root (default: this script's)")
    parser.add_argument("--list", action="store_true", help="print every class and its test files")
    args = parser.parse_args()

    classes = production_classes(args.source)
    seen = {name for _, name, _ in classes}
    problems = []
    for folder, name, header in classes:
        files = covering_files(args.source, folder, name, header)
        if args.list:
            status = ", ".join(files) if files else ("exempt" if name in EXEMPT else
                                                      "pending" if name in PENDING else "MISSING")
            print("%-14s %-40s %-40s %s" % (folder, name, header, status))
        if name in EXEMPT and name in PENDING:
            problems.append("%s is both exempt and pending" % name)
        elif files and name in EXEMPT:
            problems.append("%s/%s has %s: remove it from EXEMPT" % (folder, name, files[0]))
        elif files and name in PENDING:
            problems.append("%s/%s has %s: remove it from PENDING" % (folder, name, files[0]))
        elif not files and name not in EXEMPT and name not in PENDING:
            problems.append("%s (%s/%s) has no test file: Testing/%s/Test%s.cxx (or .py)"
                            % (name, folder, header, folder, name))
    for listed, kind in ((EXEMPT, "EXEMPT"), (PENDING, "PENDING")):
        for name in sorted(set(listed) - seen):
            problems.append("%s names %s, which no header of %s defines: remove it"
                            % (kind, name, ", ".join(PRODUCTION_FOLDERS)))

    for name in sorted(PENDING):
        if name in seen:
            print("pending: %s (%s)" % (name, PENDING[name]))
    for problem in problems:
        print("ERROR: " + problem)
    tested = sum(1 for folder, name, header in classes if covering_files(args.source, folder, name, header))
    print("%d classes: %d with their test file, %d exempt (data), %d pending, %d problems"
          % (len(classes), tested, len(seen & set(EXEMPT)), len(seen & set(PENDING)), len(problems)))
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
