"""Reading the text corpus: one sample per line, UTF-8.

The whole corpus is read and checked before anything is written, so a bad corpus leaves no
output behind. Lines end at LF; a CR before the LF (CRLF files) and a UTF-8 byte-order mark at
the start of the file are not part of the text. Blank lines (nothing but white space) are not
samples: they are skipped and counted, the usual separator between paragraphs.
"""
from __future__ import annotations

import dataclasses
import hashlib


class CorpusError(Exception):
    """A corpus that cannot be used; the message names the file and, for bad bytes, where."""


# Longest line accepted, in bytes of UTF-8. A line is one image; past this the image would be
# wider than the rasterizer's largest target (16384 px) at any legible size, and a file without
# newlines (a binary passed by mistake) is refused before it is shaped.
MAX_LINE_BYTES = 1 << 16


@dataclasses.dataclass(frozen=True)
class Corpus:
    """The samples of a corpus: texts[i] was read from line line_numbers[i] (1-based)."""
    path: str
    texts: tuple
    line_numbers: tuple
    sha256: str
    skipped_invalid: int
    skipped_blank: int


def read_corpus(path: str, *, skip_invalid: bool = False) -> Corpus:
    """Reads and checks the corpus at path.

    Invalid UTF-8 is an error naming the line (1-based) and the byte offset in the file
    (0-based) of the first bad byte; with skip_invalid the line is dropped and counted instead.
    A corpus with no sample left is an error. OSError (missing, unreadable) is turned into a
    CorpusError naming the path.
    """
    try:
        with open(path, "rb") as f:
            data = f.read()
    except IsADirectoryError:
        raise CorpusError(f"corpus '{path}' is a directory, not a text file") from None
    except OSError as e:
        raise CorpusError(f"cannot read corpus '{path}': {e.strerror or e}") from None
    digest = hashlib.sha256(data).hexdigest()
    offset = 3 if data.startswith(b"\xef\xbb\xbf") else 0
    texts, numbers = [], []
    skipped_invalid = skipped_blank = 0
    line_no = 0
    while offset < len(data):
        end = data.find(b"\n", offset)
        next_offset = len(data) if end < 0 else end + 1
        raw = data[offset:len(data) if end < 0 else end]
        line_no += 1
        if raw.endswith(b"\r"):
            raw = raw[:-1]
        try:
            text = raw.decode("utf-8")
        except UnicodeDecodeError as e:
            if skip_invalid:
                skipped_invalid += 1
                offset = next_offset
                continue
            raise CorpusError(f"corpus '{path}': invalid UTF-8 on line {line_no} at byte offset "
                              f"{offset + e.start} (byte 0x{raw[e.start]:02x}: {e.reason}); "
                              f"--skip-invalid drops such lines") from None
        if len(raw) > MAX_LINE_BYTES:
            raise CorpusError(f"corpus '{path}': line {line_no} is {len(raw)} bytes long, more "
                              f"than the {MAX_LINE_BYTES} a sample may have")
        if text.strip():
            texts.append(text)
            numbers.append(line_no)
        else:
            skipped_blank += 1
        offset = next_offset
    if not texts:
        what = "is empty" if not data else "holds no sample (every line is blank or invalid)"
        raise CorpusError(f"corpus '{path}' {what}")
    return Corpus(path=path, texts=tuple(texts), line_numbers=tuple(numbers), sha256=digest,
                  skipped_invalid=skipped_invalid, skipped_blank=skipped_blank)
