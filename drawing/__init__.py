"""Drawing sheets: solved plans in, SVG out. Only this package knows SVG."""
