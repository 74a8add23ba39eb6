// Fragment stage of the shadow pass: only depth is written, so there is nothing to compute.
void main() {}
