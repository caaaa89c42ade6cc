"""hstmon.SourceError: a bad circuit file, parameter file or log, located as the CLI locates it."""
from __future__ import annotations


class SourceError(ValueError):
    """A located error in a text source (log, circuit or parameter file).

    Attributes: ``file`` (the path, or the DataFrame's name), ``line`` and ``column``
    (1-based; 0 = no position: e.g. a file that cannot be opened) and ``message``.
    ``str(e)`` is the CLI's ``file:line:column: error: message``. For a DataFrame, ``line``
    is the row as a CSV file of its columns would have it (header line 1, first row line 2)
    and ``column`` the 1-based column number.
    """

    def __init__(self, file: str, line: int, column: int, message: str) -> None:
        self.file = file
        self.line = int(line)
        self.column = int(column)
        self.message = message
        super().__init__(self._text())

    def _text(self) -> str:
        if self.line == 0:
            return f"{self.file}: error: {self.message}"
        return f"{self.file}:{self.line}:{self.column}: error: {self.message}"

    def __str__(self) -> str:
        return self._text()

    def __reduce__(self):  # pickles across processes (a Dask worker's error)
        return (SourceError, (self.file, self.line, self.column, self.message))
