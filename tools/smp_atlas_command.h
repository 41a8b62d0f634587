// Copyright (c) 2026 The Stretch_minimizing_parameterization authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// smp-parameterize --atlas: any polygon soup in, a texture atlas out. Part of
// smp_parameterize.cpp (its options, messages and report writer), kept apart so that the disk
// path and the atlas path each read in one place.

#ifndef SMP_TOOLS_ATLAS_COMMAND_H
#define SMP_TOOLS_ATLAS_COMMAND_H

namespace {

int run_atlas(const Options& o)
{
  const auto start = std::chrono::steady_clock::now();
  check_input_file(o);
  std::vector<Point_3> points;
  std::vector<std::vector<std::size_t> > polygons;
  std::string error;
  if(!smp_tools::read_soup(o.input, points, polygons, error))
    die(error);
  const double read_seconds = seconds_since(start);
  if(!o.quiet)
    std::cout << "read " << points.size() << " vertices, " << polygons.size() << " polygons" << std::endl;

  // progress on long runs: a line per stage, and at most one a second within a stage
  double shown = 0.;
  auto progress = [&](const SMP::Atlas_progress& p) {
    static const char* const names[] = {"input", "flattening", "packing", "done"};
    if(o.quiet || p.stage == SMP::Atlas_stage::DONE || (p.done < p.total && p.seconds < shown + 1.))
      return;
    shown = p.seconds;
    std::cout << "  " << names[int(p.stage)] << ": " << p.done << " of " << p.total
              << (p.stage == SMP::Atlas_stage::FLATTENING ? " charts" : p.stage == SMP::Atlas_stage::PACKING ? " packings" : "")
              << ", " << std::setprecision(3) << p.seconds << " s" << std::endl;
  };
  namespace P = SMP::parameters;
  const SMP::Atlas atlas = SMP::make_atlas(points, polygons,
      P::max_stretch(o.max_stretch, P::resolution(unsigned(o.resolution), P::gutter(o.gutter)).visitor(progress))
          .number_of_threads(unsigned(o.threads)));
  const SMP::Atlas_report& r = atlas.report;
  if(r.status != SMP::OK)
    die("no atlas of " + o.input + ": " + SMP::error_message(r.status) + ": " + r.message);
  if(!o.quiet)
    std::cout << "atlas: " << r.charts << " charts, L2 stretch " << std::setprecision(6) << r.l2_stretch << ", Linf "
              << r.linf_stretch << ", seams " << std::setprecision(3) << 100. * r.seam_length / r.edge_length
              << "% of the edge length, utilization " << r.utilization << ", " << r.seconds << " s" << std::endl;

  // ---- write: the input's vertices and polygons, a uv per corner
  const auto t2 = std::chrono::steady_clock::now();
  const fs::path dir = output_folder(o);
  const std::string name = fs::path(o.input).stem().string();
  std::vector<std::string> outputs;
  {
    smp_tools::Text obj;
    obj << "# " << name << ": texture atlas by smp-parameterize --atlas (" << r.charts << " charts)\nmtllib " << name << ".mtl\n";
    for(const Point_3& p : points)
      obj << "v " << p.x() << ' ' << p.y() << ' ' << p.z() << '\n';
    for(const auto& polygon : atlas.uv)
      for(const auto& q : polygon)
        obj << "vt " << q[0] << " " << q[1] << "\n";
    obj << "usemtl checker\n";
    std::size_t vt = 1;
    for(const auto& polygon : polygons) {
      obj << "f";
      for(std::size_t v : polygon)
        obj << " " << v + 1 << "/" << vt++;
      obj << "\n";
    }
    write_textured_obj(dir, name, obj.str(), outputs);
  }
  const double write_seconds = seconds_since(t2);

  // ---- pictures: the polygons split as the atlas split them (a fan where one turns like the
  // polygon, else the region it bounds: a fan from a corner draws a non-convex polygon wrong),
  // coloured by the stretch of their triangles and by chart
  const auto t3 = std::chrono::steady_clock::now();
  if(o.pictures) {
    smp_tools::Textured_mesh picture;
    for(const Point_3& p : points)
      picture.xyz.push_back({p.x(), p.y(), p.z()});
    SMP::internal::Atlas_triangles split;
    SMP::internal::make_atlas_triangles(points, polygons, split); // as make_atlas() did: it succeeded
    double a2 = 0., a3 = 0.;
    for(std::size_t t = 0; t < split.corner.size(); ++t) {
      const std::size_t f = split.polygon[t];
      const std::array<int, 3>& i = split.corner[t];
      std::array<std::array<double, 2>, 3> uv;
      for(int j = 0; j < 3; ++j) uv[j] = atlas.uv[f][std::size_t(i[j])];
      const Point_3 &a = points[polygons[f][std::size_t(i[0])]], &b = points[polygons[f][std::size_t(i[1])]],
                    &c = points[polygons[f][std::size_t(i[2])]];
      const SMP::Face_stretch s = SMP::face_stretch(a, b, c, Point_2(uv[0][0], uv[0][1]), Point_2(uv[1][0], uv[1][1]),
                                                    Point_2(uv[2][0], uv[2][1]));
      if(std::isfinite(s.l2) && s.area_3d > 0.) { a2 += std::abs(s.area_uv); a3 += s.area_3d; }
      picture.faces.push_back({int(polygons[f][std::size_t(i[0])]), int(polygons[f][std::size_t(i[1])]),
                               int(polygons[f][std::size_t(i[2])])});
      picture.corner_uv.push_back(uv);
      picture.face_stretch.push_back(std::isfinite(s.l2) ? s.l2 : 0.);
      picture.face_chart.push_back(int(atlas.chart[f]));
    }
    const double normalization = a3 > 0. ? std::sqrt(a2 / a3) : 1.;
    for(double& s : picture.face_stretch) s *= normalization;
    write_pictures(dir, name, picture, o, 64, outputs);
  }
  const double render_seconds = seconds_since(t3);

  // ---- report
  Json report;
  report["input"] = o.input;
  report["mesh"] = {{"vertices", points.size()}, {"polygons", polygons.size()}, {"triangles", r.triangles},
                    {"welded_vertices", r.welded_vertices}, {"flat_polygons", r.flat_polygons}};
  report["method"] = "atlas";
  report["options"] = {{"max_stretch", o.max_stretch}, {"resolution", o.resolution}, {"gutter", o.gutter}};
  report["status"] = SMP::error_message(r.status);
  report["atlas"] = {{"charts", r.charts}, {"l2_stretch", r.l2_stretch}, {"linf_stretch", r.linf_stretch},
                     {"flipped_faces", r.flipped_faces}, {"seam_length", r.seam_length},
                     {"edge_length", r.edge_length}, {"utilization", r.utilization}};
  report["seconds"] = {{"read", read_seconds}, {"input", r.seconds_input}, {"cutting", r.seconds_cutting},
                       {"parameterization", r.seconds_parameterization}, {"packing", r.seconds_packing},
                       {"atlas", r.seconds}, {"write", write_seconds}, {"pictures", render_seconds}};
  write_report(dir, report, outputs);
  if(!o.quiet)
    std::cout << "wrote " << fs::absolute(dir).string() << "/{" << name << ".obj, report.json"
              << (o.pictures ? ", *.png" : "") << "}" << std::endl;
  return EXIT_SUCCESS;
}

} // namespace

#endif // SMP_TOOLS_ATLAS_COMMAND_H
