"""The names the command line imports from the tables of every command, each from its own
module (:mod:`.compare`, :mod:`.inspect`, :mod:`.counterweight`, :mod:`.torque`,
:mod:`.regress`, :mod:`.search`, :mod:`.family`, and :mod:`.table` for what they share)."""

from .compare import compare_parts, compare_tables
from .counterweight import WEIGHT_COLUMNS, balance_summary, balance_tables
from .family import family_parts, family_tables
from .inspect import list_table, list_tables, show_table
from .regress import regression_tables
from .search import search_rows, search_summary, search_tables
from .table import order_parts, order_values, part_headers, part_rows, render
from .torque import steadiness_text, torque_summary, torque_tables

__all__ = ["render", "compare_parts", "compare_tables", "part_rows", "part_headers", "order_parts",
           "balance_tables", "balance_summary", "list_table", "list_tables", "show_table",
           "regression_tables", "torque_tables", "torque_summary", "steadiness_text",
           "search_tables", "search_summary", "search_rows", "family_parts", "family_tables",
           "order_values", "WEIGHT_COLUMNS"]
