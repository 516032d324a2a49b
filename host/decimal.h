/* decimal: the plain decimal numbers the host's text formats accept
 * (scene files, OBJ): [+-] digits [. digits] [(e|E) [+-] digits], with at
 * least one mantissa digit. strtod also takes hex floats, "inf", "nan(...)"
 * and leading spaces; these files take none of them.
 *
 * decimal_is_plain: 1 when the n bytes at s are one plain decimal number.
 * decimal_why_not: why they are not, where a reason is worth naming ("NaN
 * or infinity not allowed", "hexadecimal numbers not allowed"), else NULL. */
#ifndef FXRT_HOST_DECIMAL_H
#define FXRT_HOST_DECIMAL_H

#include <stddef.h>

static inline int decimal_digits(const char *s, size_t n, size_t *i)
{
    size_t start = *i;
    while (*i < n && s[*i] >= '0' && s[*i] <= '9')
        (*i)++;
    return (int)(*i - start);
}

static inline int decimal_is_plain(const char *s, size_t n)
{
    size_t i = 0;
    if (i < n && (s[i] == '+' || s[i] == '-'))
        i++;
    int digits = decimal_digits(s, n, &i);
    if (i < n && s[i] == '.') {
        i++;
        digits += decimal_digits(s, n, &i);
    }
    if (digits == 0)
        return 0;
    if (i < n && (s[i] == 'e' || s[i] == 'E')) {
        i++;
        if (i < n && (s[i] == '+' || s[i] == '-'))
            i++;
        if (decimal_digits(s, n, &i) == 0)
            return 0;
    }
    return i == n;
}

/* Does the text at s + i start with the lower-case word w, in any case?
 * (Without <ctype.h>, whose functions depend on the locale.) */
static inline int decimal_starts_ci(const char *s, size_t n, size_t i, const char *w)
{
    for (; *w; w++, i++) {
        char c = i < n ? s[i] : '\0';
        if (c >= 'A' && c <= 'Z')
            c = (char)(c - 'A' + 'a');
        if (c != *w)
            return 0;
    }
    return 1;
}

static inline const char *decimal_why_not(const char *s, size_t n)
{
    size_t i = n > 0 && (s[0] == '+' || s[0] == '-') ? 1 : 0;
    if (decimal_starts_ci(s, n, i, "nan") || decimal_starts_ci(s, n, i, "inf"))
        return "NaN or infinity not allowed";
    if (decimal_starts_ci(s, n, i, "0x"))
        return "hexadecimal numbers not allowed";
    return NULL;
}

#endif
