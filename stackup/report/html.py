"""The report's markdown as one self-contained HTML page (figures embedded)."""

from __future__ import annotations

import base64
import html
import re
from pathlib import Path

_STYLE = """body{font-family:system-ui,sans-serif;max-width:1200px;margin:2em auto;padding:0 1em;color:#222;line-height:1.45}
table{border-collapse:collapse;font-size:.85em;margin:1em 0}th,td{border:1px solid #ccc;padding:.25em .5em;text-align:right}
th{background:#f3f3f3}td:first-child,th:first-child{text-align:left}img{max-width:100%}code{background:#f3f3f3;padding:0 .2em}
nav{background:#f7f7f7;border:1px solid #ddd;padding:.4em .8em;margin:1em 0;font-size:.9em}nav a{margin-right:1em}
.verdict{border-left:4px solid #2a7;padding:.2em 1em;background:#f4fbf7}
pre{background:#f7f7f7;border:1px solid #ddd;padding:.6em;font-size:.8em;overflow-x:auto;white-space:pre-wrap}"""


def anchor(title):
    """The id of a heading: lower case, words joined by hyphens."""
    return re.sub(r"[^a-z0-9]+", "-", title.lower()).strip("-")


def _inline(text):
    """Escape and render the inline markdown the report uses: `code`, **bold** and [links](#anchor)."""
    text = html.escape(text)
    text = re.sub(r"`([^`]+)`", r"<code>\1</code>", text)
    text = re.sub(r"\*\*([^*]+)\*\*", r"<strong>\1</strong>", text)
    return re.sub(r"\[([^\]]+)\]\((#[a-z0-9-]+)\)", r'<a href="\2">\1</a>', text)


def markdown_to_html(text, folder):
    """The report's markdown as one self-contained HTML page (figures embedded as base64 PNG).

    Handles exactly what :func:`stackup.report.write_report` writes:
    headings (with ids), paragraphs, pipe tables, bullet lists, fenced text blocks, images, a
    ``Contents:`` line as a navigation bar and the block between
    ``<!-- verdict -->`` and ``<!-- /verdict -->`` as the highlighted verdict.
    """
    body, table, items, code = [], [], [], None

    def flush():
        if table:
            head, *rows = [[_inline(c.strip()) for c in r.strip().strip("|").split("|")]
                           for r in table if not set(r) <= set("|-: ")]
            body.append("<table><tr>" + "".join(f"<th>{c}</th>" for c in head) + "</tr>"
                        + "".join("<tr>" + "".join(f"<td>{c}</td>" for c in r) + "</tr>" for r in rows) + "</table>")
            table.clear()
        if items:
            body.append("<ul>" + "".join(f"<li>{_inline(i)}</li>" for i in items) + "</ul>")
            items.clear()

    for line in text.splitlines():
        if code is not None:  # inside a fenced block: kept verbatim until the closing fence
            if line.startswith("```"):
                body.append("<pre>" + html.escape("\n".join(code)) + "</pre>")
                code = None
            else:
                code.append(line)
            continue
        if line.startswith("```"):
            flush()
            code = []
            continue
        if line.startswith("|"):
            table.append(line)
            continue
        if line.startswith("- "):
            items.append(line[2:])
            continue
        flush()
        image = re.fullmatch(r"!\[([^\]]*)\]\(([^)]+)\)", line.strip())
        if line.strip() == "<!-- verdict -->":
            body.append('<div class="verdict">')
        elif line.strip() == "<!-- /verdict -->":
            body.append("</div>")
        elif image:
            data = base64.b64encode((Path(folder) / image.group(2)).read_bytes()).decode()
            body.append(f'<p><img alt="{_inline(image.group(1))}" src="data:image/png;base64,{data}"></p>')
        elif line.startswith("#"):
            level = len(line) - len(line.lstrip("#"))
            title = line[level:].strip()
            body.append(f'<h{level} id="{anchor(title)}">{_inline(title)}</h{level}>')
        elif line.startswith("Contents:"):
            body.append(f"<nav>{_inline(line)}</nav>")
        elif line.strip():
            body.append(f"<p>{_inline(line)}</p>")
    flush()
    title = _inline(text.splitlines()[0].lstrip("# ")) if text else "stackup report"
    return (f"<!DOCTYPE html><html><head><meta charset='utf-8'><title>{title}</title><style>{_STYLE}</style>"
            f"</head><body>{''.join(body)}</body></html>")
