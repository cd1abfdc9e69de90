// api_cxx.cpp: a C++17 program outside the project, built against an installed
// libgranwave (tests/test_install_api.sh): the headers declare C symbols
// (extern "C"), so a C++ caller links them; it drives a study through the
// index as a binding does and checks the answer against the model's own call.
//
// Checks (exit status = number of failures): the version; the "chain" study at
// N = 1, v_imp = 0.3 m/s (tolerances 1e-12) against gw_chain_collide on the same
// column, bit for bit, and against the closed form F_max(1) (F.13) to 1e-6;
// a refused value names the parameter; NULL arguments are refused.
#include <granwave.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

static int failures;

static void check(bool ok, const std::string &what)
{
    std::printf("%s: %s\n", ok ? "PASS" : "FAIL", what.c_str());
    failures += !ok;
}

int main(int argc, char **argv)
{
    check(argc > 1 && std::string(gw_version()) == argv[1] && std::string(GW_VERSION) == argv[1],
          std::string("version ") + gw_version());

    const gw_study *st = gw_study_find("chain");
    check(st != nullptr, "gw_study_find(\"chain\")");
    if (!st)
        return failures;
    std::vector<unsigned char> setup(st->params_size), out(st->fields_size);
    gw_err err{};
    check(st->init(setup.data()) == GW_OK, "init");
    const gw_param *t = st->params();
    int rc = gw_param_set(t, setup.data(), "vimp", "0.3", &err);
    rc = rc ? rc : gw_param_set(t, setup.data(), "rtol", "1e-12", &err);
    rc = rc ? rc : gw_param_set(t, setup.data(), "atol", "1e-12", &err);
    check(rc == GW_OK, std::string("set vimp, rtol, atol ") + err.msg);
    rc = st->run(setup.data(), out.data(), nullptr, nullptr, &err);
    check(rc == GW_OK, std::string("run ") + err.msg);
    const gw_param *row = gw_param_find(st->fields(), "f_max");
    double f_study = NAN;
    if (row)
        std::memcpy(&f_study, out.data() + row->offset, sizeof f_study);
    st->free_out(out.data());
    st->clear(setup.data());

    gw_chain_params p = gw_chain_params_default();
    p.n = 1;
    p.v_imp = 0.3;
    gw_chain_run_opts o = gw_chain_run_opts_default();
    o.sp.rtol = o.sp.atol = 1e-12;
    gw_chain *c = nullptr;
    gw_chain_result r{};
    rc = gw_chain_create(&p, &c, &err);
    rc = rc ? rc : gw_chain_collide(c, &o, &r, &err);
    check(rc == GW_OK, std::string("gw_chain_collide ") + err.msg);
    const double f1 = gw_chain_fmax1(p.mass, p.kwall, p.v_imp);
    check(r.f_max == f_study, "the study's f_max equals gw_chain_collide's: " + std::to_string(f_study));
    check(std::fabs(r.f_max - f1) <= 1e-6 * f1, "F_max(1) within 1e-6 of F.13: " + std::to_string(r.f_max) +
                                                    " N against " + std::to_string(f1) + " N");
    gw_chain_result_free(&r);
    gw_chain_free(c);

    std::vector<unsigned char> s2(st->params_size);
    st->init(s2.data());
    rc = gw_param_set(t, s2.data(), "vimp", "-1", &err);
    check(rc == GW_EINVAL && std::strncmp(err.msg, "vimp: ", 6) == 0, std::string("refusal: ") + err.msg);
    st->clear(s2.data());
    rc = st->run(nullptr, nullptr, nullptr, nullptr, &err);
    check(rc == GW_EINVAL && std::strstr(err.msg, "is NULL"), std::string("NULL setup: ") + err.msg);
    return failures;
}
