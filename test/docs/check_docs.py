#!/usr/bin/env python3
"""The documented commands, run: every command of README.md and doc/*.md (doc/testing.md).

  check_docs.py --static          every command block is covered, links and images resolve, no
                                  issue numbers (no master needed)
  check_docs.py --page README.md  runs the page's commands against a master (a rostest): background
                                  blocks first, then `run` blocks and transcripts in page order

A fenced block with `$ ` lines is a transcript: each command's output must match the lines under
it (numbers to 1e-9 relative; the values of `seq`, `secs`, `nsecs` are not compared). A ```sh
block is preceded by `<!-- doc-test: KIND ... -->`: background until NAME, run, run-by FILE,
options-of SCRIPT. ```text (synopses) and code in other languages are not commands.
"""
import glob
import os
import re
import signal
import subprocess
import sys
import time
import unittest

REPO = os.path.realpath(os.path.join(os.path.dirname(os.path.realpath(__file__)), "..", ".."))
NUMBER = re.compile(r"[-+]?(?:\d+\.\d*|\.\d+|\d+)(?:[eE][-+]?\d+)?")
VOLATILE = re.compile(r"^(\s*(?:seq|secs|nsecs):).*$")
MARKER = re.compile(r"<!--\s*doc-test:\s*(.*?)\s*-->")


def pages():
    return ["README.md"] + sorted(os.path.relpath(p, REPO)
                                  for p in glob.glob(os.path.join(REPO, "doc", "*.md")))


def blocks(page):
    """Fenced blocks of a page: (line number, language, marker or None, lines)."""
    lines = open(os.path.join(REPO, page)).read().split("\n")
    found, i = [], 0
    while i < len(lines):
        if lines[i].startswith("```"):
            lang = lines[i][3:].strip()
            start, body = i + 1, []
            i += 1
            while i < len(lines) and not lines[i].startswith("```"):
                body.append(lines[i])
                i += 1
            prev = next((lines[k] for k in range(start - 2, -1, -1) if lines[k].strip()), "")
            marker = MARKER.search(prev)
            found.append((start, lang, marker.group(1) if marker else None, body))
        i += 1
    return found


def commands(body):
    """The command lines of a ```sh block, comments and blank lines left out."""
    out = []
    for line in body:
        line = re.sub(r"\s+#.*$", "", line).strip()
        if line and not line.startswith("#"):
            out.append(line)
    return out


def transcript(body):
    """[(command, expected output lines)] of a transcript block."""
    steps = []
    for line in body:
        if line.startswith("$ "):
            steps.append((line[2:], []))
        elif steps:
            steps[-1][1].append(line)
    return [(c, "\n".join(out).strip("\n")) for c, out in steps]


def normalise(text):
    return "\n".join(VOLATILE.sub(r"\1 *", l.rstrip()) for l in text.strip("\n").split("\n"))


def same_output(expected, actual):
    """Equal but for numbers within 1e-9 (relative) and the volatile header fields."""
    e, a = normalise(expected), normalise(actual)
    if NUMBER.split(e) != NUMBER.split(a):
        return False
    en, an = NUMBER.findall(e), NUMBER.findall(a)
    if len(en) != len(an):
        return False
    for x, y in zip(en, an):
        fx, fy = float(x), float(y)
        if abs(fx - fy) > 1e-9 * max(1.0, abs(fx), abs(fy)) and not (x == y):
            return False
    return True


def code_of(path):
    """A script's or launch file's text without comment lines, "${repo}/x" read as x."""
    text = "\n".join(l for l in open(os.path.join(REPO, path)).read().split("\n")
                     if not l.lstrip().startswith("#"))
    text = re.sub(r'"\$\{repo\}/([^"]+)"', r"\1", text)
    return re.sub(r"\s+", " ", text)


def static_problems():
    problems = []
    for page in pages():
        text = open(os.path.join(REPO, page)).read()
        for m in re.finditer(r"\bissues? \d+|\(#\d+\)", text):
            problems.append("%s: cites an issue number: %r" % (page, m.group(0)))
        for m in re.finditer(r"\]\(([^)#\s]+)(#[^)]*)?\)", text):
            target = m.group(1)
            if re.match(r"[a-z]+://", target):
                continue
            if not os.path.exists(os.path.join(REPO, os.path.dirname(page), target)):
                problems.append("%s: link to a missing file: %s" % (page, target))
        for line, lang, marker, body in blocks(page):
            where = "%s:%d" % (page, line)
            is_transcript = any(l.startswith("$ ") for l in body)
            if is_transcript or lang in ("text", "cpp", "python", "yaml", "xml"):
                continue
            if lang != "sh":
                problems.append("%s: a block without a language and without `$ ` lines" % where)
                continue
            if marker is None:
                problems.append("%s: a ```sh block without <!-- doc-test: ... -->" % where)
                continue
            kind, _, arg = marker.partition(" ")
            if kind in ("background", "run"):
                continue
            if kind == "run-by":
                code = " ".join(code_of(path) for path in arg.split())
                for command in commands(body):
                    if re.sub(r"\s+", " ", command) not in code:
                        problems.append("%s: `%s` is not run by %s" % (where, command, arg))
            elif kind == "options-of":
                code = open(os.path.join(REPO, arg)).read()
                for command in commands(body):
                    if not command.startswith("bash " + arg):
                        problems.append("%s: `%s` does not run %s" % (where, command, arg))
                    # --rviz-arg passes the next word to rviz, not to the script.
                    own = re.sub(r"--rviz-arg \S+", "--rviz-arg", command)
                    for option in re.findall(r"(?<!\S)(--[a-z][a-z-]*)", own):
                        if not re.search(r"(^|[\s|(])%s[)|]" % re.escape(option), code, re.M):
                            problems.append("%s: %s does not accept %s" % (where, arg, option))
            else:
                problems.append("%s: unknown doc-test kind %r" % (where, kind))
    return problems


def shell(command, timeout):
    done = subprocess.run(["bash", "-c", "export PATH=/usr/bin:$PATH; " + command], cwd=REPO,
                          stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                          universal_newlines=True, timeout=timeout)
    return done.returncode, done.stdout


def ready(what):
    """A service exists, or (`subscriber TOPIC`) a topic has a subscriber."""
    if what.startswith("subscriber "):
        status, out = shell("rostopic info " + what.split()[1], 30)
        return status == 0 and re.search(r"Subscribers:\s*\n\s*\*", out) is not None
    status, _ = shell("rosservice list | grep -qx " + what, 30)
    return status == 0


class DocumentedCommands(unittest.TestCase):
    page = None

    def test_static(self):
        if self.page:
            self.skipTest("live run of " + self.page)
        problems = static_problems()
        self.assertEqual(problems, [], "\n".join(problems))

    def test_page_commands(self):
        if not self.page:
            self.skipTest("static check only")
        started = []
        try:
            found = blocks(self.page)
            for line, lang, marker, body in found:
                if marker and marker.startswith("background"):
                    wait = marker.split(" until ", 1)[1]
                    for command in commands(body):
                        started.append(subprocess.Popen(
                            ["bash", "-c", "export PATH=/usr/bin:$PATH; exec " + command],
                            cwd=REPO, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                            start_new_session=True))
                    deadline = time.time() + 90
                    while not ready(wait):
                        self.assertLess(time.time(), deadline,
                                        "%s:%d: never ready: %s" % (self.page, line, wait))
                        for p in started:
                            self.assertIsNone(p.poll(), "%s:%d: exited" % (self.page, line))
                        time.sleep(1)
            ran = 0
            for line, lang, marker, body in found:
                where = "%s:%d" % (self.page, line)
                if marker == "run":
                    for command in commands(body):
                        status, out = shell(command, 60)
                        self.assertEqual(status, 0, "%s: `%s`:\n%s" % (where, command, out))
                        ran += 1
                for command, expected in transcript(body):
                    status, out = shell(command, 120)
                    self.assertTrue(same_output(expected, out),
                                    "%s: `%s` printed\n%s\ninstead of\n%s"
                                    % (where, command, out, expected))
                    ran += 1
            self.assertGreater(ran, 0, "no command run on " + self.page)
        finally:
            for p in started:
                if p.poll() is None:
                    os.killpg(p.pid, signal.SIGINT)
            for p in started:
                try:
                    p.wait(20)
                except subprocess.TimeoutExpired:
                    os.killpg(p.pid, signal.SIGKILL)


if __name__ == "__main__":
    args = [a for a in sys.argv[1:] if not a.startswith("__") and not a.startswith("--gtest")]
    if "--page" in args:
        DocumentedCommands.page = args[args.index("--page") + 1]
    name = "doc_" + (os.path.splitext(os.path.basename(DocumentedCommands.page))[0].lower()
                     if DocumentedCommands.page else "static")
    import rostest
    # rostest's own --gtest_output=xml:PATH tells where the results go (run_tests gives a results
    # directory of its own); everything else was ours.
    rostest.rosrun("ellipse_collision", name, DocumentedCommands,
                   sys.argv[:1] + [a for a in sys.argv[1:] if a.startswith("--gtest_output")])
