"""Markdown generated for the docs from the code's own definitions, at build time.

Not part of the installed package: the ``generate`` hook imports these modules by the names
that the pages' ``<!-- generate: module:function -->`` markers give.
"""
