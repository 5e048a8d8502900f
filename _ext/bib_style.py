"""A pybtex style whose bibliography labels match the author-year citations in the text.

The book cites "[Bui, 2016]"; with the default alpha style the bibliography listed the
same work as "[Bui16]", a second key to look up. This style labels each entry with
its authors' surnames and year, as the text does, and sorts by author, year, title.
"""

from pybtex.plugin import register_plugin
from pybtex.style.formatting.unsrt import Style as UnsrtStyle
from pybtex.style.labels import BaseLabelStyle


def _surnames(entry):
    persons = entry.persons.get("author") or entry.persons.get("editor") or []
    names = [" ".join(p.prelast_names + p.last_names) for p in persons]
    names = [n.replace("{", "").replace("}", "") for n in names]
    if not names:
        return entry.fields.get("key", entry.key)
    if len(names) == 1:
        return names[0]
    if len(names) == 2:
        return f"{names[0]} and {names[1]}"
    return f"{names[0]} et al."


class AuthorYearLabelStyle(BaseLabelStyle):
    """Labels "Surname, Year" ("n.d." without a year)."""

    def format_labels(self, sorted_entries):
        for entry in sorted_entries:
            yield f"{_surnames(entry)}, {entry.fields.get('year', 'n.d.')}"


class AuthorYearStyle(UnsrtStyle):
    """unsrt formatting with author-year labels, sorted by author, year and title."""

    default_label_style = AuthorYearLabelStyle
    default_sorting_style = "author_year_title"


def setup(app):
    register_plugin("pybtex.style.formatting", "authoryear", AuthorYearStyle)
    return {"parallel_read_safe": True, "parallel_write_safe": True}
