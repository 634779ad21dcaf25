"""The comparisons with the thesis: every value or formula the thesis prints that camdyn can
compute, each with its reference and tolerance (:mod:`.check`), gathered by topic
(:mod:`.suite`) and run by `camdyn check`, by the test suite and, for the statements beside
a figure, by `camdyn figures`."""
