// The water plane's pixels go to the stencil buffer only; no colour is written.
void main() {}
