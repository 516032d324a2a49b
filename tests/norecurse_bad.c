/* Negative control for tests/norecurse.sh: each function here recurses or
 * calls through a pointer, which the checker must report. Never linked. */
int bad_self(int n);
int bad_even(int n);
int bad_odd(int n);
int bad_pointer(int n);
extern void bad_sink(int *p);

/* Not a tail call (the product), so -O2 keeps a call. */
int bad_self(int n)
{
    int a[4] = {n, n, n, n};
    bad_sink(a);
    return n > 0 ? n * bad_self(n - 1) + a[1] : 1;
}

int bad_even(int n)
{
    int a[2] = {n, 0};
    bad_sink(a);
    return n == 0 ? 1 : bad_odd(n - 1) * 3 + a[1];
}

int bad_odd(int n)
{
    int a[2] = {n, 1};
    bad_sink(a);
    return n == 0 ? 0 : bad_even(n - 1) * 5 + a[1];
}

int (*volatile bad_fn)(int) = bad_self;
int bad_pointer(int n)
{
    return bad_fn(n);
}
