"""``safestate mutate``: the mutation score of a model's properties (issue 28).

Generated first-order mutants of the spec's own definitions (`operators.py`,
`generate.py`), each classified with the model's CI cfg (`classify.py`): killed by a
property, survived (a behaviour difference no property notices, shown by the product
search of `product.py`), equivalent, timeout or error.  See docs/mutate.md.
"""
