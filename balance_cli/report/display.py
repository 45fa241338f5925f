"""Display units and text safety: the only place where newtons become per-cylinder figures,
kN, kgf or lbf for a table, where figures get their significant digits, and where names are
made safe for Markdown and plain-text tables."""

from dataclasses import dataclass

from ..units import UNIT_SYSTEMS, significant, unit_system

__all__ = ["Scale", "markdown_text", "plain_text", "figure"]

#: significant figures of a force, moment or torque in a table
DIGITS = 4


def figure(value, digits=DIGITS):
    """A force, moment, torque or mass as table text: ``digits`` significant figures."""
    return significant(value, digits)


@dataclass(frozen=True)
class Scale:
    """How forces and moments are shown: per cylinder (× m_rec·r·ω²·n), or in one system of
    units (:data:`~balance_cli.units.UNIT_SYSTEMS`: N and N·m, kN and kN·m, MN and MN·m,
    kgf and kgf·m, lbf and lbf·ft).

    Moments are always absolute, in the moment unit of ``units``.
    """

    absolute: bool = False
    units: str = "N"

    @classmethod
    def of(cls, absolute, units):
        """The scale of the command-line options: any unit but N implies absolute forces; the
        unit's name in any letter case."""
        units = unit_system(units)
        return cls(absolute=absolute or units != "N", units=units)

    @property
    def force_label(self) -> str:
        return self.units if self.absolute else "per cyl"

    @property
    def force_unit_text(self) -> str:
        """The force unit in words, for titles and axis labels."""
        return self.units if self.absolute else "× m_rec·r·ω² per cylinder"

    @property
    def moment_label(self) -> str:
        return UNIT_SYSTEMS[self.units][1]

    @property
    def column_force(self) -> str:
        """The force unit in a CSV column name: per_cyl, N, kN, MN, kgf or lbf."""
        return self.units if self.absolute else "per_cyl"

    @property
    def column_moment(self) -> str:
        """The moment unit in a CSV column name: Nm, kNm, MNm, kgfm or lbfft."""
        return self.moment_label.replace("·", "")

    def force(self, value_n, per_cylinder_unit_n):
        if not self.absolute:
            return value_n / per_cylinder_unit_n
        return value_n / UNIT_SYSTEMS[self.units][0]

    def moment(self, value_nm):
        return value_nm / UNIT_SYSTEMS[self.units][2]


def plain_text(value):
    """One line of text for a table cell: line breaks and tabs become spaces."""
    return " ".join(str(value).split()) if any(c in str(value) for c in "\r\n\t\v\f") else str(value)


_MARKDOWN = str.maketrans({"|": r"\|", "<": "&lt;", ">": "&gt;", "&": "&amp;", "`": r"\`",
                           "*": r"\*", "_": r"\_", "[": r"\[", "]": r"\]", "\\": "\\\\"})


def markdown_text(value):
    """Text that a Markdown renderer shows as written: one line, no table breaks, no HTML."""
    return plain_text(value).translate(_MARKDOWN)
