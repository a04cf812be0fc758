"""The first ``` block after a heading of a Markdown page, as lines: what the project's checks
read their lists from (tools/check_module_map.py: README.md's module map; tools/check_modules.py:
docs/DESIGN.md's dependency graph). Exits with a message naming the tool when the heading is
missing."""
import sys


def block_after(path, heading, tool):
    text = open(path, encoding='utf-8').read()
    at = text.find(heading)
    if at < 0:
        sys.exit('%s: %s has no "%s"' % (tool, path, heading))
    start = text.index('```', at) + 3
    return text[text.index('\n', start) + 1:text.index('```', start)].split('\n')
