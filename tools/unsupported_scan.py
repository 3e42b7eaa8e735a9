#!/usr/bin/env python3
"""List every feature povtrace refuses in a scene, not only the first.

povtrace stops at the first 'unsupported: X' error. This tool copies the scene's folder to a scratch folder, runs
povtrace, deletes the refused item (a `keyword { ... }` block, or the keyword and the rest of its line) from the
scratch copy of the file that names it (copying an include file next to the scene first), and repeats until the
scene renders or an error other than 'unsupported' appears. Only scratch copies are edited.

usage: unsupported_scan.py [--povtrace BIN] [--timeout S] [--max N] scene.pov [more.pov ...]
prints one line per scene: path, the refused features in the order found, and how the last run ended.
"""
import argparse, os, re, shutil, subprocess, sys, tempfile

ERR = re.compile(r'^(?P<file>[^:\n]+):(?P<line>\d+):(?P<col>\d+): error: unsupported: (?P<what>.+?) is a POV-Ray '
                 r'feature that povtrace does not render yet(?: \(written at (?P<wfile>[^:]+):(?P<wline>\d+):'
                 r'(?P<wcol>\d+))?', re.M)


def remove_item(path, line, col):
    text = open(path, encoding='latin-1').read()
    lines = text.split('\n')
    start = sum(len(l) + 1 for l in lines[:line - 1]) + col - 1
    m = re.match(r'[A-Za-z_][A-Za-z_0-9]*', text[start:])
    end = start + (m.end() if m else 1)
    rest = text[end:]
    ws = len(rest) - len(rest.lstrip())
    if rest[ws:ws + 1] == '{':
        depth, i = 0, end + ws
        while i < len(text):
            if text[i] == '{': depth += 1
            elif text[i] == '}':
                depth -= 1
                if depth == 0: break
            i += 1
        end = i + 1
    else:
        nl = text.find('\n', end)
        end = len(text) if nl < 0 else nl
    open(path, 'w', encoding='latin-1').write(text[:start] + ' ' * 0 + text[end:])


def scan(scene, binary, timeout, max_iter, extra):
    scene = os.path.abspath(scene)
    work = tempfile.mkdtemp(prefix='uscan-')
    src_dir = os.path.dirname(scene)
    dst_dir = os.path.join(work, 'scene')
    shutil.copytree(src_dir, dst_dir, symlinks=False)
    dst_scene = os.path.join(dst_dir, os.path.basename(scene))
    found, status = [], ''
    for _ in range(max_iter):
        cmd = [binary, '+W160', '+H120', '-D', '-F', '+L' + dst_dir] + extra + [dst_scene]
        try:
            p = subprocess.run(cmd, cwd=dst_dir, capture_output=True, text=True, timeout=timeout)
        except subprocess.TimeoutExpired:
            status = 'timeout after %ss (parsed; rendering)' % timeout
            break
        out = p.stdout + p.stderr
        m = ERR.search(out)
        if not m:
            status = 'renders' if p.returncode == 0 else 'other error: ' + out.strip().splitlines()[-1][:160]
            break
        found.append(m.group('what'))
        f, l, c = (m.group('wfile'), m.group('wline'), m.group('wcol')) if m.group('wfile') else \
                  (m.group('file'), m.group('line'), m.group('col'))
        f = f.strip()
        if not f.startswith(dst_dir):
            local = os.path.join(dst_dir, os.path.basename(f))
            if not os.path.exists(local) or os.path.realpath(os.path.dirname(f)) != os.path.realpath(src_dir):
                shutil.copy(f, local)
            f = local
        remove_item(f, int(l), int(c))
    shutil.rmtree(work, ignore_errors=True)
    return found, status


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('--povtrace', default=os.path.join(os.path.dirname(__file__), '..', 'build', 'povtrace'))
    ap.add_argument('--timeout', type=float, default=60)
    ap.add_argument('--max', type=int, default=25)
    ap.add_argument('--lib', action='append', default=['/usr/share/povray-3.7/include'])
    ap.add_argument('scenes', nargs='+')
    a = ap.parse_args()
    extra = ['+L' + l for l in a.lib]
    for s in a.scenes:
        found, status = scan(s, os.path.abspath(a.povtrace), a.timeout, a.max, extra)
        uniq = []
        for f in found:
            if f not in uniq: uniq.append(f)
        print('%s\t%s\t%s' % (s, '; '.join(uniq) if uniq else '-', status), flush=True)


if __name__ == '__main__':
    main()
