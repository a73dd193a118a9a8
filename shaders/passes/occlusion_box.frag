#version 450 core
// The occlusion test writes nothing: the depth test and the query's sample count are its result.
layout(early_fragment_tests) in;

void main() {}
