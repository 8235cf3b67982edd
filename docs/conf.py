"""Sphinx configuration of the user guide (scripts/guide builds it).

The source folder is docs/: the guide's chapters in docs/guide/ and the
documents beside them (model.md, validation.md, performance.md, ...) are
pages of one site, so that their links between one another resolve.
Markdown is read by MyST; the Python API reference is autodoc's, from the
installed package's docstrings.
"""

project = "soilcut"
author = "the soilcut developers"
root_doc = "guide/index"
extensions = ["myst_parser", "sphinx.ext.autodoc", "sphinx.ext.napoleon"]
source_suffix = {".md": "markdown"}
# The studies' folders hold their outputs and notes, linked as files.
exclude_patterns = ["studies", "scripts", "img", "guide/extra"]
myst_heading_anchors = 4
myst_enable_extensions = ["dollarmath"]
html_theme = "alabaster"
# target/guide/index.html: a link to the first page, guide/index.html.
html_extra_path = ["guide/extra"]
html_title = "soilcut user guide"
autodoc_member_order = "bysource"
autodoc_typehints = "description"
