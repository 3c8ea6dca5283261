"""Python-style layout for the generated lexer: INDENT/DEDENT tokens and implicit line joining.

The grammar's lexer emits one NEWLINE token per line break, carrying the whitespace that starts the
next line. This wrapper (1) drops line breaks inside ``(...)`` and ``[...]``, (2) folds blank and
comment-only lines, (3) compares each logical line's indentation with a stack and emits INDENT or
DEDENT tokens, like CPython's tokenizer, (4) closes every open block at the end of the file,
so that a missing final newline is harmless, and (5) reads a number and a name after it on the same
line (``20 kph``, as other OS2 grammars allow) as one physical literal: a number followed by a name
has no other reading.
"""

from __future__ import annotations

from collections import deque

from antlr4 import InputStream
from antlr4.Token import CommonToken, Token

from ..errors import Diagnostic, SourceLocation
from .generated.OpenScenario2Lexer import OpenScenario2Lexer
from .generated.OpenScenario2Parser import OpenScenario2Parser

# Declared in the grammar's tokens{} block; ANTLR numbers them in the parser only.
INDENT = OpenScenario2Parser.INDENT
DEDENT = OpenScenario2Parser.DEDENT

TAB_STOP = 8


def indentation_width(whitespace: str) -> int:
    column = 0
    for char in whitespace:
        column = (column // TAB_STOP + 1) * TAB_STOP if char == "\t" else column + 1
    return column


class IndentingLexer(OpenScenario2Lexer):
    def __init__(self, input: InputStream, path: str) -> None:
        super().__init__(input)
        self.path = path
        self.diagnostics: list[Diagnostic] = []
        self._pending: deque[Token] = deque()
        self._lookahead: Token | None = None
        self._indents = [0]
        self._depth = 0
        self._emitted_any = False
        self._last_type: int | None = None

    def nextToken(self) -> Token:
        while not self._pending:
            self._advance()
        token = self._pending.popleft()
        self._last_type = token.type
        return token

    def _raw(self) -> Token:
        if self._lookahead is not None:
            token, self._lookahead = self._lookahead, None
            return token
        return super().nextToken()

    def _advance(self) -> None:
        token = self._raw()
        kind = token.type
        if kind == Token.EOF:
            self._close(token)
            return
        if kind == self.NEWLINE:
            if self._depth > 0:
                return  # implicit line joining inside brackets
            self._line_end(token)
            return
        if kind in (self.IntLiteral, self.FloatLiteral):
            token = self._with_unit(token)
        if kind in (self.LPAREN, self.LBRACK):
            self._depth += 1
        elif kind in (self.RPAREN, self.RBRACK):
            self._depth = max(0, self._depth - 1)
        self._emit(token)

    def _with_unit(self, number: Token) -> Token:
        """``20 kph``: the number and the name after it as the physical literal ``20kph``."""
        following = self._raw()
        if following.type != self.Identifier or following.line != number.line or following.text.startswith("|"):
            self._lookahead = following
            return number
        token = CommonToken(
            source=number.source,
            type=self.PhysicalLiteral,
            channel=Token.DEFAULT_CHANNEL,
            start=number.start,
            stop=following.stop,
        )
        token.text = number.text + following.text
        token.line = number.line
        token.column = number.column
        return token

    def _line_end(self, newline: Token) -> None:
        following = super().nextToken()
        while following.type == self.NEWLINE:  # blank or comment-only lines
            newline = following
            following = super().nextToken()
        if following.type == Token.EOF:
            self._close(following)
            return
        self._lookahead = following
        if not self._emitted_any:
            return  # leading blank lines
        self._emit(self._make(self.NEWLINE, "\n", newline))
        text = newline.text.lstrip("\r\n")
        width = indentation_width(text)
        if width > self._indents[-1]:
            self._indents.append(width)
            self._emit(self._make(INDENT, text, following))
            return
        while width < self._indents[-1]:
            self._indents.pop()
            self._emit(self._make(DEDENT, "", following))
        if width != self._indents[-1]:
            self.diagnostics.append(
                Diagnostic(
                    SourceLocation(self.path, following.line, following.column + 1),
                    "this line is dedented to a column that no enclosing block uses",
                    hint="indent it to match the block it belongs to",
                )
            )
            self._indents.append(width)

    def _close(self, eof: Token) -> None:
        if self._emitted_any and self._last_emitted_type != self.NEWLINE:
            self._emit(self._make(self.NEWLINE, "\n", eof))
        while len(self._indents) > 1:
            self._indents.pop()
            self._emit(self._make(DEDENT, "", eof))
        self._pending.append(eof)

    def _emit(self, token: Token) -> None:
        self._emitted_any = True
        self._last_emitted_type = token.type
        self._pending.append(token)

    def _make(self, kind: int, text: str, at: Token) -> Token:
        token = CommonToken(
            source=at.source, type=kind, channel=Token.DEFAULT_CHANNEL, start=at.start, stop=at.start - 1
        )
        token.text = text
        token.line = at.line
        token.column = at.column
        return token
