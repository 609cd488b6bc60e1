# Gathers the `GPUH <tag> <chunk> <json>` console lines of gpu.html from the headless shell's log
# into one JSON file ({ tag: [value, ...] }) and prints a summary.
# Usage: python3 collect.py gpu.log gpu.json
import json
import re
import sys

chunks = {}
for line in open(sys.argv[1], encoding='utf-8', errors='replace'):
    found = re.search(r'"GPUH (\S+) (\d+) (.*)", source:', line)
    if found:
        chunks.setdefault(found.group(1), []).append((int(found.group(2)), found.group(3)))

results = {}
for tag, parts in chunks.items():
    # A tag logged twice (a step run again) has its chunks numbered from 0 again: split at each 0.
    values, current = [], ''
    for index, part in parts:
        if index == 0 and current:
            values.append(current)
            current = ''
        current += part
    values.append(current)
    for value in values:
        try:
            results.setdefault(tag, []).append(json.loads(value))
        except ValueError:
            results.setdefault(tag, []).append({'unparsed': value[:500]})

with open(sys.argv[2], 'w', encoding='utf-8') as out:
    json.dump(results, out, indent=1)
print('tags:', {tag: len(values) for tag, values in results.items()})
for tag in ('probe', 'sa-meta', 'error', 'step', 'nm', 'hero'):
    if tag in results:
        print(tag, json.dumps(results[tag])[:1500])
for table in results.get('sa-table', []):
    print(table)
