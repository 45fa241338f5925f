"""Display units and text safety: the only place where newtons become per-cylinder figures or
kgf for a table, and where names are made safe for Markdown and plain-text tables."""

from dataclasses import dataclass

from ..units import n_to_kgf

__all__ = ["Scale", "markdown_text", "plain_text"]


@dataclass(frozen=True)
class Scale:
    """How forces and moments are shown: per cylinder (× m_rec·r·ω²·n), or in N or kgf.

    Moments are always absolute: N·m, or kgf·m when ``units`` is "kgf".
    """

    absolute: bool = False
    units: str = "N"

    @classmethod
    def of(cls, absolute, units):
        """The scale of the command-line options: kgf implies absolute forces."""
        return cls(absolute=absolute or units == "kgf", units=units)

    @property
    def force_label(self) -> str:
        return self.units if self.absolute else "per cyl"

    @property
    def force_unit_text(self) -> str:
        """The force unit in words, for titles and axis labels."""
        return self.units if self.absolute else "× m_rec·r·ω² per cylinder"

    @property
    def moment_label(self) -> str:
        return "kgf·m" if self.units == "kgf" else "N·m"

    @property
    def column_force(self) -> str:
        """The force unit in a CSV column name: per_cyl, N or kgf."""
        return self.units if self.absolute else "per_cyl"

    @property
    def column_moment(self) -> str:
        """The moment unit in a CSV column name: Nm or kgfm."""
        return self.moment_label.replace("·", "")

    def force(self, value_n, per_cylinder_unit_n):
        if not self.absolute:
            return value_n / per_cylinder_unit_n
        return n_to_kgf(value_n) if self.units == "kgf" else value_n

    def moment(self, value_nm):
        return n_to_kgf(value_nm) if self.units == "kgf" else value_nm


def plain_text(value):
    """One line of text for a table cell: line breaks and tabs become spaces."""
    return " ".join(str(value).split()) if any(c in str(value) for c in "\r\n\t\v\f") else str(value)


_MARKDOWN = str.maketrans({"|": r"\|", "<": "&lt;", ">": "&gt;", "&": "&amp;", "`": r"\`",
                           "*": r"\*", "_": r"\_", "[": r"\[", "]": r"\]", "\\": "\\\\"})


def markdown_text(value):
    """Text that a Markdown renderer shows as written: one line, no table breaks, no HTML."""
    return plain_text(value).translate(_MARKDOWN)
