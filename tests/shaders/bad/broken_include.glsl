// Included by include_error.comp; line 5 has a type error.

float broken() {
  float x = 1.0;
  return x + vec2(1.0);
}
