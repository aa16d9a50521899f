"""report.md and report.html: the same text, tables and pictures; the
HTML page embeds the pictures so that it can be mailed on its own."""
import base64
import html
import os


def write_report(report, folder, heading, outcome_text, rows, pictures, solver, checks, notes):
    """report.md, and report.html with the same text and the pictures
    embedded, so that it can be mailed on its own."""
    md = ["# formsolve run report", "", f"Output folder: `{folder}`", "", f"## {heading}", ""]
    md += [t for line in outcome_text for t in (line, "")]
    md += ["## Key numbers", "", "| quantity | value |", "|---|---|"] + [f"| {q} | {v} |" for q, v in rows] + [""]
    page = ["<!DOCTYPE html>", "<html><head><meta charset='utf-8'><title>formsolve run report</title>",
            "<style>body{font-family:sans-serif;max-width:60em;margin:auto}td,th{border:1px solid #ccc;"
            "padding:0.2em 0.5em}table{border-collapse:collapse}img{max-width:100%}</style></head><body>",
            "<h1>formsolve run report</h1>", f"<p>Output folder: <code>{html.escape(folder)}</code></p>",
            f"<h2>{html.escape(heading)}</h2>"]
    for line in outcome_text:
        bold = line.startswith("**") and line.endswith("**")
        text = html.escape(line.strip("*") if bold else line)
        page.append(f"<p><strong>{text}</strong></p>" if bold else f"<p>{text}</p>")
    page.append("<h2>Key numbers</h2>")

    def table(entries):
        page.append("<table><tr><th>quantity</th><th>value</th></tr>")
        page.extend(f"<tr><td>{html.escape(q)}</td><td>{html.escape(v)}</td></tr>" for q, v in entries)
        page.append("</table>")

    def figures(entries, level):
        for heading, name, caption in entries:
            md.extend([f"{'#' * level} {heading}", "", f"![{heading}]({name})", "", caption, ""])
            with open(os.path.join(report, name), "rb") as png:
                data = base64.b64encode(png.read()).decode()
            page.append(f"<h{level}>{html.escape(heading)}</h{level}>")
            page.append(f"<img alt='{html.escape(heading)}' src='data:image/png;base64,{data}'>")
            page.append(f"<p>{html.escape(caption)}</p>")

    table(rows)
    figures(pictures, 2)
    md += ["## Solver checks", "", "| quantity | value |", "|---|---|"] + [f"| {q} | {v} |" for q, v in solver] + [""]
    page.append("<h2>Solver checks</h2>")
    table(solver)
    figures(checks, 3)
    if notes:
        md += ["## Not in this report", ""] + [f"- {n}" for n in notes] + [""]
        page.append("<h2>Not in this report</h2><ul>")
        page.extend(f"<li>{html.escape(n)}</li>" for n in notes)
        page.append("</ul>")
    page.append("</body></html>")
    with open(os.path.join(report, "report.md"), "w") as out:
        out.write("\n".join(md))
    with open(os.path.join(report, "report.html"), "w") as out:
        out.write("\n".join(page) + "\n")

