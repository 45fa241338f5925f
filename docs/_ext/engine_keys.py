from docutils.parsers.rst import Directive


class EngineKeysDirective(Directive):
    def run(self):
        return []


class UnitsDirective(Directive):
    def run(self):
        return []
