"""A value as one Markdown table cell, as renderer/output/escape.cpp's markdownCell writes it: HTML's
three specials as entities, line breaks as spaces, and | \\ ` * _ [ ] backslash-escaped, so a scene or
configuration name stays text in the cell it lands in."""

_ENTITIES = {"&": "&amp;", "<": "&lt;", ">": "&gt;"}


def cell(value):
    out = []
    text = str(value).replace("\r\n", "\n")
    for c in text:
        if c in _ENTITIES:
            out.append(_ENTITIES[c])
        elif c in "\r\n":
            out.append(" ")
        elif c in "|\\`*_[]":
            out.append("\\" + c)
        else:
            out.append(c)
    return "".join(out)
