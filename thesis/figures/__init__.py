"""The figures of the thesis and the paper that the models determine, and the design charts:
`camdyn figures` draws them (:mod:`.build`, one topic module per chapter, :mod:`.charts` for
the design tools) and writes an index page (:mod:`.index`) showing each picture beside its
number, caption and the printed statements it reproduces, computed now, each with its error."""
