#!/usr/bin/env python3
"""The guide's links hold: every ](target) in README.md, docs/**/*.md, scenes/gallery/README.md and
bench/experiments/README.md names a file that exists, and a #anchor names a heading of that file (GitHub's
slugs). Links to web addresses are not followed (no network here).
    check_links.py [SOURCE_DIR]"""
import pathlib, re, sys, unicodedata
root = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else '.')
files = [root / 'README.md', root / 'scenes/gallery/README.md', root / 'bench/experiments/README.md'] + sorted((root / 'docs').rglob('*.md'))
def slugs(path):
    out, seen = set(), {}
    in_code = False
    for line in path.read_text(encoding='utf-8').splitlines():
        if line.startswith('```'): in_code = not in_code; continue
        if in_code: continue
        m = re.match(r'^#{1,6}\s+(.*?)\s*#*\s*$', line)
        if not m: continue
        t = m.group(1).lower()
        t = ''.join(c for c in t if c.isalnum() or c in ' -_' or unicodedata.category(c).startswith('L'))
        t = t.replace(' ', '-')
        n = seen.get(t, 0); seen[t] = n + 1
        out.add(t if n == 0 else f'{t}-{n}')
    return out
bad = 0
for f in files:
    text = f.read_text(encoding='utf-8')
    text = re.sub(r'```.*?```', '', text, flags=re.S)
    text = re.sub(r'`[^`\n]*`', '', text)
    for m in re.finditer(r'\]\(([^)\s]+)(?:\s+"[^"]*")?\)', text):
        target = m.group(1)
        if re.match(r'^[a-z]+:', target): continue
        path, _, anchor = target.partition('#')
        dest = (f.parent / path).resolve() if path else f
        if not dest.exists():
            print(f'{f.relative_to(root)}: missing file {target}'); bad += 1; continue
        if anchor and dest.suffix == '.md' and anchor not in slugs(dest):
            print(f'{f.relative_to(root)}: missing anchor {target}'); bad += 1
print(f'{len(files)} files checked, {bad} broken links'); sys.exit(1 if bad else 0)
