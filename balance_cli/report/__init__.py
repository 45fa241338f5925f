"""Turning results into text, tables and documents. Nothing here computes balance."""
