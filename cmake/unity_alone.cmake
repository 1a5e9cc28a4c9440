# The sources compiled on their own where the rest goes in unity batches (the web build's page, the
# sanitizer tree's core): their file-local names (anonymous namespaces, statics) are also another
# source's, which one translation unit cannot hold twice.
set(OASIS_UNITY_ALONE pixel_probe file_output gbuffer_layout png_text svg_plot)
